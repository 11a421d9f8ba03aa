#include "indentation/node_row.hpp"

namespace si {
namespace {

std::array<int, 5> node_equations(const DofMap& dofs, int node) {
  std::array<int, 5> eq{};
  for (int l = 0; l < 5; ++l) eq[l] = dofs.equation(DofMap::dof(node, l));
  return eq;
}

}  // namespace

void add_node_row_pattern(const DofMap& dofs, int node, int m, int alpha, Triplets& t) {
  const std::array<int, 5> eq = node_equations(dofs, node);
  for (int r : eq) {
    if (r < 0) continue;
    t.emplace_back(r, m, 0.0);
    t.emplace_back(m, r, 0.0);
    for (int c : eq)
      if (c >= 0) t.emplace_back(r, c, 0.0);
  }
  t.emplace_back(m, m, 0.0);
  if (alpha >= 0) t.emplace_back(m, alpha, 0.0);
}

NodeRowSlots locate_node_row(const DofMap& dofs, int node, int m, int alpha,
                             const SparseMatrix& J) {
  NodeRowSlots s;
  s.eq = node_equations(dofs, node);
  for (int r = 0; r < 5; ++r) {
    s.column[r] = s.eq[r] >= 0 ? value_slot(J, s.eq[r], m) : -1;
    s.row[r] = s.eq[r] >= 0 ? value_slot(J, m, s.eq[r]) : -1;
    for (int c = 0; c < 5; ++c)
      s.block[5 * r + c] = s.eq[r] >= 0 && s.eq[c] >= 0 ? value_slot(J, s.eq[r], s.eq[c]) : -1;
  }
  s.diagonal = value_slot(J, m, m);
  s.alpha_column = alpha >= 0 ? value_slot(J, m, alpha) : -1;
  return s;
}

void add_node_row_force(const NodeRowSlots& s, const NodeGap& g, double lambda,
                        Eigen::VectorXd& r_free) {
  for (int l = 0; l < 5; ++l)
    if (s.eq[l] >= 0) r_free[s.eq[l]] -= lambda * g.gradient[l];
}

void add_node_row_entries(const NodeRowSlots& s, const NodeGap& g, double lambda, double b,
                          bool derivative, double* J) {
  for (int r = 0; r < 5; ++r) {
    if (s.eq[r] < 0) continue;
    J[s.column[r]] -= g.gradient[r];
    J[s.row[r]] += b * g.gradient[r];
    if (derivative)
      for (int c = 0; c < 5; ++c)
        if (s.eq[c] >= 0) J[s.block[5 * r + c]] -= lambda * g.gradient_derivative(r, c);
  }
}

ContactJacobianRow condensed_node_row(const NodeRowSlots& s, const NodeGap& g, double a, double b) {
  ContactJacobianRow row;
  row.eq = s.eq;
  for (int r = 0; r < 5; ++r) row.gradient[r] = g.gradient[r];
  row.a = a;
  row.b = b;
  return row;
}

}  // namespace si
