// Linearly implicit Rosenbrock 4(3) method with Shampine's (1982) coefficients (the GRK4T-type
// scheme of Kaps and Rentrop used by Numerical Recipes' stiff integrator), as a GSL odeiv2 step
// type. Each stage solves (I - gamma h J) x = b with the system's ShiftedSolver: by default J = M + v w^T
// from the model's structured Jacobian, block-diagonal solves plus Sherman-Morrison, O(n) per stage
// instead of O(n^3); the variational system supplies its block-triangular solver the same way.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <cmath>
#include <memory>
#include <vector>

#include "rbcstab/integrate/detail/gsl_context.hpp"

namespace rbcstab::detail {

namespace {
constexpr double GAM = 1.0 / 2, A21 = 2.0, A31 = 48.0 / 25, A32 = 6.0 / 25, C21 = -8.0, C31 = 372.0 / 25,
                 C32 = 12.0 / 5, C41 = -112.0 / 125, C42 = -54.0 / 125, C43 = -2.0 / 5, B1 = 19.0 / 9, B2 = 1.0 / 2,
                 B3 = 25.0 / 108, B4 = 125.0 / 108, E1 = 17.0 / 54, E2 = 7.0 / 36, E3 = 0.0, E4 = 125.0 / 108,
                 C1X = 1.0 / 2, C2X = -3.0 / 2, C3X = 121.0 / 50, C4X = 29.0 / 250, A2X = 1.0, A3X = 3.0 / 5;

struct State {
  explicit State(std::size_t n) : f0(n), dfdt(n), g1(n), g2(n), g3(n), g4(n), ytmp(n), ftmp(n), b(n) {}
  std::vector<double> f0, dfdt, g1, g2, g3, g4, ytmp, ftmp, b;
  // Made lazily from the integrated system at the first step (ros_alloc does not see the system);
  // the State belongs to one driver, i.e. one integrate() call, so nothing is shared between threads.
  std::unique_ptr<ShiftedSolver> solver;
};

void* ros_alloc(std::size_t dim) { return new State(dim); }
void ros_free(void* s) { delete static_cast<State*>(s); }
int ros_reset(void*, std::size_t) { return GSL_SUCCESS; }
unsigned int ros_order(void*) { return 4; }
int ros_set_driver(void*, const gsl_odeiv2_driver*) { return GSL_SUCCESS; }

int ros_apply(void* vstate, std::size_t n, double t, double h, double y[], double yerr[], const double dydt_in[],
              double dydt_out[], const gsl_odeiv2_system* sys) {
  auto& s = *static_cast<State*>(vstate);
  auto* ctx = static_cast<GslContext*>(sys->params);
  if (dydt_in) {
    std::copy(dydt_in, dydt_in + n, s.f0.begin());
  } else if (int rc = GSL_ODEIV_FN_EVAL(sys, t, y, s.f0.data()); rc != GSL_SUCCESS) {
    return rc;
  }
  ++ctx->counters->jacobian_evaluations;
  if (!s.solver) s.solver = ctx->system->make_shifted_solver();
  s.solver->linearize(t, {y, n}, s.dfdt);
  const double gamma_h = GAM * h;
  // A x = rhs with A = I/(gamma h) - J  <=>  (I - gamma h J) x = gamma h rhs.
  auto solve = [&](std::vector<double>& x) -> bool {
    for (std::size_t i = 0; i < n; ++i) s.b[i] *= gamma_h;
    return s.solver->solve(gamma_h, s.b, x);
  };
  for (std::size_t i = 0; i < n; ++i) s.b[i] = s.f0[i] + h * C1X * s.dfdt[i];
  if (!solve(s.g1)) return GSL_FAILURE;
  for (std::size_t i = 0; i < n; ++i) s.ytmp[i] = y[i] + A21 * s.g1[i];
  if (int rc = GSL_ODEIV_FN_EVAL(sys, t + A2X * h, s.ytmp.data(), s.ftmp.data()); rc != GSL_SUCCESS) return rc;
  for (std::size_t i = 0; i < n; ++i) s.b[i] = s.ftmp[i] + h * C2X * s.dfdt[i] + C21 * s.g1[i] / h;
  if (!solve(s.g2)) return GSL_FAILURE;
  for (std::size_t i = 0; i < n; ++i) s.ytmp[i] = y[i] + A31 * s.g1[i] + A32 * s.g2[i];
  if (int rc = GSL_ODEIV_FN_EVAL(sys, t + A3X * h, s.ytmp.data(), s.ftmp.data()); rc != GSL_SUCCESS) return rc;
  for (std::size_t i = 0; i < n; ++i) s.b[i] = s.ftmp[i] + h * C3X * s.dfdt[i] + (C31 * s.g1[i] + C32 * s.g2[i]) / h;
  if (!solve(s.g3)) return GSL_FAILURE;
  for (std::size_t i = 0; i < n; ++i)
    s.b[i] = s.ftmp[i] + h * C4X * s.dfdt[i] + (C41 * s.g1[i] + C42 * s.g2[i] + C43 * s.g3[i]) / h;
  if (!solve(s.g4)) return GSL_FAILURE;
  for (std::size_t i = 0; i < n; ++i) {
    s.ytmp[i] = y[i] + B1 * s.g1[i] + B2 * s.g2[i] + B3 * s.g3[i] + B4 * s.g4[i];
    yerr[i] = E1 * s.g1[i] + E2 * s.g2[i] + E3 * s.g3[i] + E4 * s.g4[i];
  }
  if (dydt_out) {
    if (int rc = GSL_ODEIV_FN_EVAL(sys, t + h, s.ytmp.data(), dydt_out); rc != GSL_SUCCESS) return rc;
  }
  std::copy(s.ytmp.begin(), s.ytmp.end(), y);
  return GSL_SUCCESS;
}

const gsl_odeiv2_step_type kRosenbrock = {"rosenbrock",   1,         1,         ros_alloc, ros_apply,
                                          ros_set_driver, ros_reset, ros_order, ros_free};
}  // namespace

const gsl_odeiv2_step_type* rosenbrock_step_type() { return &kRosenbrock; }

}  // namespace rbcstab::detail
