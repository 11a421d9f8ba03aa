#include "continuation/kinsol_corrector.hpp"

#include <kinsol/kinsol.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace si::cont {
namespace {

// Every SUNDIALS set-up call goes through here: a failure is a programming or installation
// error, so it throws with the call's name.
void check(int flag, const char* call) {
  if (flag < 0) {
    char* name = KINGetReturnFlagName(flag);
    std::string text = std::string(call) + " failed: " + (name ? name : "?");
    std::free(name);  // malloc'd in SUNDIALS 6.x (docs/toolchain.md §3 pitfall 6)
    throw std::runtime_error(text);
  }
}

template <class T>
T* check_ptr(T* ptr, const char* call) {
  if (ptr == nullptr) throw std::runtime_error(std::string(call) + " returned null");
  return ptr;
}

std::string flag_name(int flag) {
  char* name = KINGetReturnFlagName(flag);
  std::string text = name ? name : "?";
  std::free(name);
  return text;
}

std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", v);
  return buf;
}

double inf_norm(const Vector& v) {
  return v.size() == 0 ? 0.0 : v.lpNorm<Eigen::Infinity>();
}

Eigen::Map<const Vector> view(N_Vector v) {
  return {N_VGetArrayPointer(v), static_cast<Eigen::Index>(N_VGetLength(v))};
}

// Where a residual that did not converge is largest, in the system's words: a stalled
// corrector's residual often sits on one unknown (a node, a contact row), which says more than
// its norm.
std::string largest_entry(const NonlinearSystem& system, const Vector& r) {
  if (r.size() == 0) return {};
  Eigen::Index i = 0;
  r.cwiseAbs().maxCoeff(&i);
  const std::string name = system.unknown_name(static_cast<int>(i));
  return ", largest at unknown " + std::to_string(i) + (name.empty() ? "" : " (" + name + ")");
}

// What KINSOL's callbacks reach through user_data / content.
struct Adapter {
  NonlinearSystem& system;
  const NewtonSettings& settings;
  // ||R|| at each iterate where the Jacobian was formed: _inf for the convergence test, _2 for
  // the stall rule (what the line search lowers).
  struct Norms {
    double inf = 0.0, two = 0.0;
  };
  std::vector<Norms> norms;
  std::string messages;
  Vector scratch;
  bool stalled = false;  // gave up: the residual stopped falling (NewtonSettings::stall_window)

  // The system's own reason for a failed call, ahead of KINSOL's generic ones.
  void note(const char* what) {
    const std::string why = system.failure();
    messages += std::string(what) + (why.empty() ? "" : ": " + why) + "; ";
  }

  int residual(N_Vector u, N_Vector f) {
    Vector r;
    if (!system.residual(view(u), r)) return 1;
    if (r.size() != N_VGetLength(f) || !r.allFinite()) return 1;
    Eigen::Map<Vector>(N_VGetArrayPointer(f), r.size()) = r;
    return 0;
  }
  int setup(N_Vector u, N_Vector fu) {
    norms.push_back({inf_norm(view(fu)), view(fu).norm()});
    // KINSOL forms the Jacobian once per iteration (full Newton): the place to stop a creeping
    // iteration before it pays for another factorization. A failed set-up ends KINSol.
    if (has_stalled()) {
      stalled = true;
      return -1;
    }
    if (system.setup(view(u))) return 0;
    note("the Jacobian's set-up failed");
    return 1;
  }
  bool has_stalled() const {
    // On ||R||_2, which KINSOL's line search makes fall at every accepted step: ||R||_inf may
    // rise for an iteration while an active set settles and still converge (measured on the
    // D7136 plate's support frame: 0.400 -> 0.764 -> 0.098 -> 2e-6).
    const auto w = static_cast<std::size_t>(settings.stall_window);
    return w > 0 && norms.size() > w &&
           norms.back().two > settings.stall_ratio * norms[norms.size() - 1 - w].two;
  }
  int solve(N_Vector x, N_Vector b) {
    scratch = view(b);
    if (!system.solve(scratch) || !scratch.allFinite()) {
      note("the linear solve failed");
      return SUNLS_PACKAGE_FAIL_REC;
    }
    Eigen::Map<Vector>(N_VGetArrayPointer(x), scratch.size()) = scratch;
    return SUNLS_SUCCESS;
  }
};

Adapter& adapter(void* data) {
  return *static_cast<Adapter*>(data);
}

// An empty custom matrix: the system owns its Jacobian. KINSOL needs getid/zero/destroy only.
SUNMatrix make_matrix(SUNContext ctx) {
  SUNMatrix m = check_ptr(SUNMatNewEmpty(ctx), "SUNMatNewEmpty");
  m->ops->getid = [](SUNMatrix) { return SUNMATRIX_CUSTOM; };
  m->ops->zero = [](SUNMatrix) { return 0; };
  m->ops->destroy = [](SUNMatrix a) { SUNMatFreeEmpty(a); };
  return m;
}

// A DIRECT linear solver whose solve is the system's; the factorization happens in the
// Jacobian callback, which is where KINSOL hands over the current iterate.
SUNLinearSolver make_linear_solver(Adapter& data, SUNContext ctx) {
  SUNLinearSolver s = check_ptr(SUNLinSolNewEmpty(ctx), "SUNLinSolNewEmpty");
  s->content = &data;
  s->ops->gettype = [](SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; };
  s->ops->getid = [](SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; };
  s->ops->setup = [](SUNLinearSolver, SUNMatrix) { return int{SUNLS_SUCCESS}; };
  s->ops->solve = [](SUNLinearSolver ls, SUNMatrix, N_Vector x, N_Vector b, sunrealtype) {
    return adapter(ls->content).solve(x, b);
  };
  s->ops->free = [](SUNLinearSolver ls) {
    ls->content = nullptr;
    SUNLinSolFreeEmpty(ls);
    return 0;
  };
  return s;
}

// Owns the SUNDIALS objects; frees KINSOL first, then LS, matrix, vectors, context.
struct Kinsol {
  SUNContext ctx = nullptr;
  N_Vector u = nullptr;
  N_Vector scale = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver solver = nullptr;
  void* mem = nullptr;

  Kinsol() = default;
  Kinsol(const Kinsol&) = delete;
  Kinsol& operator=(const Kinsol&) = delete;
  ~Kinsol() {
    if (mem) KINFree(&mem);
    if (solver) SUNLinSolFree(solver);
    if (matrix) SUNMatDestroy(matrix);
    if (scale) N_VDestroy(scale);
    if (u) N_VDestroy(u);
    if (ctx) SUNContext_Free(&ctx);
  }
};

void configure(Kinsol& k, Adapter& data, const Vector& u0, double tolerance,
               const NewtonSettings& settings) {
  const auto n = static_cast<sunindextype>(u0.size());
  check(SUNContext_Create(nullptr, &k.ctx), "SUNContext_Create");
  k.u = check_ptr(N_VNew_Serial(n, k.ctx), "N_VNew_Serial");
  k.scale = check_ptr(N_VNew_Serial(n, k.ctx), "N_VNew_Serial");
  Eigen::Map<Vector>(N_VGetArrayPointer(k.u), u0.size()) = u0;
  N_VConst(1.0, k.scale);

  k.mem = check_ptr(KINCreate(k.ctx), "KINCreate");
  check(KINInit(
            k.mem, [](N_Vector u, N_Vector f, void* d) { return adapter(d).residual(u, f); }, k.u),
        "KINInit");
  check(KINSetUserData(k.mem, &data), "KINSetUserData");
  check(KINSetErrHandlerFn(
            k.mem,
            [](int, const char* module, const char* function, char* msg, void* d) {
              adapter(d).messages += std::string(module) + "/" + function + ": " + msg + "; ";
            },
            &data),
        "KINSetErrHandlerFn");
  k.matrix = make_matrix(k.ctx);
  k.solver = make_linear_solver(data, k.ctx);
  check(KINSetLinearSolver(k.mem, k.solver, k.matrix), "KINSetLinearSolver");
  check(KINSetJacFn(k.mem, [](N_Vector u, N_Vector fu, SUNMatrix, void* d, N_Vector,
                              N_Vector) { return adapter(d).setup(u, fu); }),
        "KINSetJacFn");
  check(KINSetMaxSetupCalls(k.mem, 1), "KINSetMaxSetupCalls");  // full Newton
  check(KINSetNumMaxIters(k.mem, settings.max_iterations), "KINSetNumMaxIters");
  check(KINSetFuncNormTol(k.mem, tolerance), "KINSetFuncNormTol");
  // A step below ~eps relative means roundoff stagnation: stop and report, do not spin.
  check(KINSetScaledStepTol(k.mem, 1e-15), "KINSetScaledStepTol");
  const double max_step =
      settings.max_step > 0.0 ? settings.max_step : 1e3 * std::max(1.0, u0.norm());
  check(KINSetMaxNewtonStep(k.mem, max_step), "KINSetMaxNewtonStep");
}

// Adapts a Problem at fixed p to the corrector's NonlinearSystem.
class FixedParameter final : public NonlinearSystem {
 public:
  FixedParameter(Problem& problem, double p) : problem_(problem), p_(p) {}
  bool residual(const Vector& u, Vector& r) override { return problem_.residual(u, p_, r); }
  bool setup(const Vector& u) override { return problem_.factorize(u, p_); }
  bool solve(Vector& b) override { return problem_.solve(b); }
  std::string failure() const override { return problem_.failure(); }
  std::string unknown_name(int i) const override { return problem_.unknown_name(i); }

 private:
  Problem& problem_;
  double p_;
};

}  // namespace

NewtonResult newton_solve(NonlinearSystem& system, Vector& u, const NewtonSettings& settings) {
  settings.validate();
  NewtonResult result;
  Vector r;
  if (!system.residual(u, r) || r.size() != u.size() || !r.allFinite()) {
    result.reason = "the residual cannot be evaluated at the starting point";
    return result;
  }
  const double r0 = inf_norm(r);
  result.residual_norms.push_back(r0);
  result.tolerance = settings.relative_tolerance * std::max(r0, settings.residual_scale);
  if (r0 <= result.tolerance) {  // nothing to do (also covers R = 0 exactly)
    result.converged = true;
    return result;
  }

  Adapter data{system, settings, {}, {}, {}};
  Kinsol k;
  configure(k, data, u, result.tolerance, settings);
  result.flag =
      KINSol(k.mem, k.u, settings.line_search ? KIN_LINESEARCH : KIN_NONE, k.scale, k.scale);
  result.flag_name = flag_name(result.flag);
  long iterations = 0;
  check(KINGetNumNonlinSolvIters(k.mem, &iterations), "KINGetNumNonlinSolvIters");
  result.iterations = static_cast<int>(iterations);
  u = view(k.u);

  // Judge convergence on the returned iterate ourselves: flag 2 (step below tolerance) is not
  // a solution unless the residual says so (docs/toolchain.md §3 pitfall 1).
  result.residual_norms.clear();
  for (const Adapter::Norms& n : data.norms) result.residual_norms.push_back(n.inf);
  if (data.stalled) {
    // KINSOL counts the iteration whose set-up refused to go on; it made no update.
    result.iterations = static_cast<int>(data.norms.size()) - 1;
    result.residual_norms.pop_back();  // the returned iterate's, pushed below
  }
  if (result.residual_norms.empty()) result.residual_norms.push_back(r0);
  const bool evaluated = system.residual(u, r) && r.allFinite();
  result.residual_norms.push_back(evaluated ? inf_norm(r) : HUGE_VAL);
  result.converged = result.flag >= 0 && evaluated && inf_norm(r) <= result.tolerance;
  if (!result.converged) {
    // Why it stopped, then where the residual is: one sentence for either cause.
    std::string cause = "KINSol returned " + result.flag_name;
    if (data.stalled) {
      const std::vector<Adapter::Norms>& n = data.norms;
      const std::size_t w = static_cast<std::size_t>(settings.stall_window);
      char ratio[32];
      std::snprintf(ratio, sizeof ratio, "%g", settings.stall_ratio);
      cause = "the residual stalled: ||F||_2 went from " + sci(n[n.size() - 1 - w].two) + " to " +
              sci(n.back().two) + " over the last " + std::to_string(w) +
              " iterations (not below " + ratio + " of where it was)";
    }
    result.reason = cause + " after " + std::to_string(result.iterations) +
                    " iterations with ||F||_inf = " + sci(result.residual_norms.back()) +
                    " > tolerance " + sci(result.tolerance);
    if (evaluated) result.reason += largest_entry(system, r);
    if (!data.messages.empty()) result.reason += " (" + data.messages + ")";
  }
  return result;
}

NewtonResult solve_at(Problem& problem, Vector& x, double p, const NewtonSettings& settings) {
  if (x.size() != problem.size())
    throw std::invalid_argument("solve_at: x has size " + std::to_string(x.size()) +
                                " but the problem has size " + std::to_string(problem.size()));
  FixedParameter system(problem, p);
  return newton_solve(system, x, settings);
}

}  // namespace si::cont
