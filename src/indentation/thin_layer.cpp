#include "indentation/thin_layer.hpp"

namespace si {

ThinLayer::ThinLayer(double compliance, const ShellPart& shell, const ContactRows& rows)
    : compliance_(compliance), shell_(shell), rows_(rows) {}

double ThinLayer::layer(const std::vector<int>& nodes, int i,
                        const Eigen::Ref<const cont::Vector>& lambda) const {
  return layer_rate(nodes[i]) * lambda[i];
}

double ThinLayer::layer_rate(int node) const {
  return compliance_ / shell_.tributary_area(node);
}

void ThinLayer::outputs(const TermPoint& p, IndentationState& out) const {
  const ShellModel& model = shell_.model();
  const std::vector<int>& nodes = rows_.candidates();
  for (int i = 0; i < rows_.size(); ++i) {
    const double lambda = p.z[rows_.first() + i];
    const double approach = layer_rate(nodes[i]) * lambda;
    out.local_energy += model.symmetry_factor * 0.5 * lambda * approach;
    if (nodes[i] == model.apex_node()) out.local_indentation = approach;
  }
}

}  // namespace si
