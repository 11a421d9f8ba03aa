#include "model/patch_fit.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "core/error.hpp"

namespace si {
namespace {

// The monomials x^i y^j, i + j <= degree, as exponent pairs in a fixed order.
std::vector<std::array<int, 2>> monomials(int degree) {
  std::vector<std::array<int, 2>> out;
  for (int total = 0; total <= degree; ++total)
    for (int j = 0; j <= total; ++j) out.push_back({total - j, j});
  return out;
}

double factorial(int n) {
  double f = 1;
  for (int k = 2; k <= n; ++k) f *= k;
  return f;
}

}  // namespace

PatchFit fit_patch(const std::vector<Vector2d>& points, const Eigen::MatrixXd& values,
                   const Vector2d& at, int degree, int nodes) {
  if (degree < 1 || degree > 4)
    throw_input("a patch fit needs a polynomial degree from 1 to 4",
                Where{"", "degree", std::to_string(degree), 0});
  if (static_cast<Eigen::Index>(points.size()) != values.rows())
    throw_input("a patch fit needs one row of values per point");
  const std::vector<std::array<int, 2>> terms = monomials(degree);
  const int wanted = std::max<int>(nodes, 2 * static_cast<int>(terms.size()));
  if (static_cast<int>(points.size()) < wanted)
    throw_input("a patch fit of degree " + std::to_string(degree) + " needs " +
                std::to_string(wanted) + " nodes, the field has " + std::to_string(points.size()));

  std::vector<int> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::partial_sort(order.begin(), order.begin() + wanted, order.end(), [&](int a, int b) {
    return (points[a] - at).squaredNorm() < (points[b] - at).squaredNorm();
  });
  order.resize(wanted);
  PatchFit out;
  out.nodes = wanted;
  out.radius = (points[order.back()] - at).norm();
  const double rho = out.radius > 0 ? out.radius : 1.0;

  Eigen::MatrixXd P(wanted, terms.size());
  Eigen::MatrixXd V(wanted, values.cols());
  for (int r = 0; r < wanted; ++r) {
    const Vector2d x = (points[order[r]] - at) / rho;
    for (size_t c = 0; c < terms.size(); ++c)
      P(r, c) = std::pow(x(0), terms[c][0]) * std::pow(x(1), terms[c][1]);
    V.row(r) = values.row(order[r]);
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(P);
  if (qr.rank() < static_cast<Eigen::Index>(terms.size()))
    throw_input("the nodes around the point do not determine a polynomial of degree " +
                std::to_string(degree) + " (too few, or aligned)");
  const Eigen::MatrixXd coefficients = qr.solve(V);

  // d^(i+j)/dx^i dy^j of the fit at the point: coefficient * i! j! / rho^(i+j).
  auto derivative = [&](int i, int j) -> Eigen::VectorXd {
    for (size_t c = 0; c < terms.size(); ++c)
      if (terms[c][0] == i && terms[c][1] == j)
        return coefficients.row(c).transpose() * factorial(i) * factorial(j) / std::pow(rho, i + j);
    return Eigen::VectorXd::Zero(values.cols());
  };
  out.value = derivative(0, 0);
  out.d1 = {derivative(1, 0), derivative(0, 1)};
  out.d2 = {derivative(2, 0), derivative(1, 1), derivative(0, 2)};
  out.d3 = {derivative(3, 0), derivative(2, 1), derivative(1, 2), derivative(0, 3)};
  return out;
}

}  // namespace si
