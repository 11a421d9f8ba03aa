#include "model/chart_assembly.hpp"

namespace si {

ChartAssembly::ChartAssembly(const Assembler& assembler, const ShellChart& chart)
    : assembler_(assembler), chart_(chart), assembly_(assembler.make_assembly()) {}

const Assembly& ChartAssembly::assemble(const Eigen::VectorXd& x, double prescribed_scale,
                                        bool tangent) {
  const bool cached = x_.size() == x.size() && x_ == x && prescribed_scale_ == prescribed_scale;
  if (cached && (has_tangent_ || !tangent)) return assembly_;
  x_.resize(0);  // invalid while assembling (an element may throw)
  chart_.states(x, prescribed_scale, states_);
  assembler_.assemble(states_, ElementRequest{true, tangent}, assembly_);
  x_ = x;
  prescribed_scale_ = prescribed_scale;
  has_tangent_ = tangent;
  ++(tangent ? tangent_assemblies_ : force_assemblies_);
  return assembly_;
}

const Assembly& ChartAssembly::at(const Eigen::VectorXd& x, double prescribed_scale) {
  return assemble(x, prescribed_scale, true);
}

const Assembly& ChartAssembly::force_at(const Eigen::VectorXd& x, double prescribed_scale) {
  return assemble(x, prescribed_scale, false);
}

}  // namespace si
