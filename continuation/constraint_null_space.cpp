#include "continuation/constraint_null_space.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace si::cont {
namespace {

using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

// Union-find over rows (path halving).
int root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Rows grouped by overlapping supports: root row -> rows.
std::map<int, std::vector<int>> overlap_groups(const RowMajor& rows) {
  const int m = static_cast<int>(rows.rows());
  std::vector<int> parent(static_cast<std::size_t>(m));
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<int> owner(static_cast<std::size_t>(rows.cols()), -1);
  for (int i = 0; i < m; ++i)
    for (RowMajor::InnerIterator it(rows, i); it; ++it) {
      int& o = owner[static_cast<std::size_t>(it.col())];
      if (o < 0)
        o = i;
      else
        parent[static_cast<std::size_t>(root(parent, i))] = root(parent, o);
    }
  std::map<int, std::vector<int>> groups;
  for (int i = 0; i < m; ++i) groups[root(parent, i)].push_back(i);
  return groups;
}

struct GroupBasis {
  std::vector<int> dofs;  // the group's columns, ascending
  Matrix null;            // d_g x (d_g - r): orthonormal basis of the group's null space
  int rank = 0;
};

GroupBasis group_basis(const RowMajor& rows, const std::vector<int>& members, double tolerance) {
  GroupBasis g;
  for (int i : members)
    for (RowMajor::InnerIterator it(rows, i); it; ++it) g.dofs.push_back(it.col());
  std::sort(g.dofs.begin(), g.dofs.end());
  g.dofs.erase(std::unique(g.dofs.begin(), g.dofs.end()), g.dofs.end());
  const auto d = static_cast<Eigen::Index>(g.dofs.size());
  Matrix bt = Matrix::Zero(d, static_cast<Eigen::Index>(members.size()));  // B'
  for (std::size_t c = 0; c < members.size(); ++c)
    for (RowMajor::InnerIterator it(rows, members[c]); it; ++it) {
      if (!std::isfinite(it.value()))
        throw std::invalid_argument("constraint row " + std::to_string(members[c]) +
                                    " has a non-finite entry");
      const auto r = std::lower_bound(g.dofs.begin(), g.dofs.end(), it.col()) - g.dofs.begin();
      bt(r, static_cast<Eigen::Index>(c)) += it.value();
    }
  Eigen::ColPivHouseholderQR<Matrix> qr(bt.rows(), bt.cols());
  qr.setThreshold(tolerance);
  qr.compute(bt);
  g.rank = static_cast<int>(qr.rank());
  const Matrix q = qr.householderQ();
  g.null = q.rightCols(d - g.rank);
  return g;
}

}  // namespace

NullSpaceBasis constraint_null_space(const SparseMatrix& A, double rank_tolerance) {
  const RowMajor rows = A;
  const auto n = static_cast<int>(A.cols());
  std::vector<int> group_of(static_cast<std::size_t>(n), -1);  // dof -> index in `groups`
  std::vector<GroupBasis> groups;
  for (const auto& [first, members] : overlap_groups(rows)) {
    if (rows.row(members.front()).nonZeros() == 0 && members.size() == 1) continue;  // empty row
    groups.push_back(group_basis(rows, members, rank_tolerance));
    for (int dof : groups.back().dofs)
      group_of[static_cast<std::size_t>(dof)] = static_cast<int>(groups.size()) - 1;
  }
  NullSpaceBasis out;
  std::vector<Eigen::Triplet<double, int>> entries;
  int column = 0;
  for (int dof = 0; dof < n; ++dof) {
    const int g = group_of[static_cast<std::size_t>(dof)];
    if (g < 0) {
      entries.emplace_back(dof, column++, 1.0);
      continue;
    }
    const GroupBasis& basis = groups[static_cast<std::size_t>(g)];
    if (basis.dofs.front() != dof) continue;  // emitted at the group's first dof
    out.rank += basis.rank;
    for (Eigen::Index c = 0; c < basis.null.cols(); ++c, ++column)
      for (std::size_t r = 0; r < basis.dofs.size(); ++r)
        entries.emplace_back(basis.dofs[r], column, basis.null(static_cast<Eigen::Index>(r), c));
  }
  out.Z.resize(n, column);
  out.Z.setFromTriplets(entries.begin(), entries.end());
  return out;
}

SparseMatrix restrict_to_null_space(const SparseMatrix& K, const SparseMatrix& Z) {
  const SparseMatrix KZ = K * Z;
  const SparseMatrix reduced = Z.transpose() * KZ;
  const SparseMatrix transposed = reduced.transpose();
  return 0.5 * (reduced + transposed);
}

}  // namespace si::cont
