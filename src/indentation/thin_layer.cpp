#include "indentation/thin_layer.hpp"

namespace si {

ThinLayer::ThinLayer(double compliance, const ShellPart& shell, const ContactRows& rows)
    : compliance_(compliance), shell_(shell), rows_(rows) {}

double ThinLayer::layer(int node, double lambda) const {
  return compliance_ * lambda / shell_.tributary_area(node);
}

void ThinLayer::outputs(const TermPoint& p, IndentationState& out) const {
  const ShellModel& model = shell_.model();
  const std::vector<int>& nodes = rows_.candidates();
  for (int i = 0; i < rows_.size(); ++i) {
    const double lambda = p.z[rows_.first() + i];
    out.local_energy += model.symmetry_factor * 0.5 * lambda * layer(nodes[i], lambda);
    if (nodes[i] == model.apex_node()) out.local_indentation = layer(nodes[i], lambda);
  }
}

}  // namespace si
