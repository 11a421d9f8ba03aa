#include "fitting/model_jacobian.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <optional>
#include <thread>

namespace si::fit {
namespace {

// y at every point, `concurrency` at a time; empty where the model failed. The first exception a
// model call throws is rethrown here once every running call has returned.
std::vector<std::optional<Eigen::VectorXd>> evaluate_all(const ModelValues& model,
                                                         const std::vector<Eigen::VectorXd>& points,
                                                         Eigen::Index m, int concurrency) {
  std::vector<std::optional<Eigen::VectorXd>> out(points.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto work = [&] {
    for (std::size_t i = next++; i < points.size(); i = next++) {
      try {
        Eigen::VectorXd y(m);
        if (model(points[i], y) && y.size() == m && y.allFinite()) out[i] = std::move(y);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        next = points.size();  // no new calls
      }
    }
  };
  const int workers = std::max(1, std::min<int>(concurrency, static_cast<int>(points.size())));
  std::vector<std::thread> threads;
  for (int w = 1; w < workers; ++w) threads.emplace_back(work);
  work();
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);
  return out;
}

}  // namespace

ModelJacobian model_jacobian(const ModelValues& model, const Eigen::VectorXd& c,
                             const Eigen::VectorXd& y0, const Eigen::VectorXd& lower,
                             const Eigen::VectorXd& upper, double relative_step,
                             DifferenceScheme scheme, int concurrency) {
  const Eigen::Index m = y0.size();
  const Eigen::Index n = c.size();
  ModelJacobian out;
  out.jacobian = Eigen::MatrixXd::Constant(m, n, std::numeric_limits<double>::quiet_NaN());
  out.steps = Eigen::VectorXd::Zero(n);
  out.central = Eigen::VectorXi::Zero(n);
  // The points of every column, known before any is evaluated: c + h e_j where it lies within
  // the bounds, and c - h e_j for a central difference or where c + h e_j does not.
  std::vector<Eigen::VectorXd> points;
  std::vector<int> plus(n, -1), minus(n, -1);
  Eigen::VectorXd h(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double width = upper[j] - lower[j];
    h[j] = std::min(relative_step * std::max(std::abs(c[j]), 0.01 * width), 0.25 * width);
    Eigen::VectorXd cp = c, cm = c;
    cp[j] = c[j] + h[j];
    cm[j] = c[j] - h[j];
    const bool up = cp[j] <= upper[j], down = cm[j] >= lower[j];
    if (up) {
      plus[j] = static_cast<int>(points.size());
      points.push_back(cp);
    }
    if (down && (scheme == DifferenceScheme::kCentral || !up)) {
      minus[j] = static_cast<int>(points.size());
      points.push_back(cm);
    }
  }
  const auto y = evaluate_all(model, points, m, concurrency);
  out.evaluations = static_cast<int>(points.size());
  const auto ok = [&](int i) { return i >= 0 && y[i].has_value(); };
  for (Eigen::Index j = 0; j < n; ++j) {
    // The step actually taken, (c + h) - (c - h), not 2h: removes the representation error.
    if (ok(plus[j]) && ok(minus[j])) {
      out.jacobian.col(j) =
          (*y[plus[j]] - *y[minus[j]]) / (points[plus[j]][j] - points[minus[j]][j]);
      out.steps[j] = h[j];
      out.central[j] = 1;
    } else if (ok(plus[j])) {
      out.jacobian.col(j) = (*y[plus[j]] - y0) / (points[plus[j]][j] - c[j]);
      out.steps[j] = h[j];
    } else if (ok(minus[j])) {
      out.jacobian.col(j) = (y0 - *y[minus[j]]) / (c[j] - points[minus[j]][j]);
      out.steps[j] = -h[j];
    } else {
      out.ok = false;
    }
  }
  return out;
}

}  // namespace si::fit
