#pragma once
// The rk8pd stepper's oracle, for its tests and benchmark: GSL's own rk8pd on a system's full state.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <span>
#include <vector>

#include "integrate/full_state.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/system.hpp"

namespace rbcstab::testing {

struct Steps {
  std::vector<std::vector<double>> samples;  // y at each grid time (none if the run failed)
  std::size_t steps = 0, failed = 0, rhs = 0;
};

struct GslCall {
  const System* system;
  std::size_t* rhs;
};
inline int gsl_f(double t, const double y[], double dydt[], void* params) {
  const auto* c = static_cast<const GslCall*>(params);
  ++*c->rhs;
  c->system->rhs(t, {y, c->system->dimension()}, {dydt, c->system->dimension()});
  return GSL_SUCCESS;
}

// GSL's rk8pd with the standard control (a_y = 1, a_dydt = 0) through the grid, as integrate() drove it.
inline Steps gsl_rk8pd(const System& s, const std::vector<double>& grid, const IntegratorOptions& o) {
  Steps r;
  GslCall call{&s, &r.rhs};
  gsl_odeiv2_system sys{gsl_f, nullptr, s.dimension(), &call};
  gsl_odeiv2_driver* d =
      gsl_odeiv2_driver_alloc_standard_new(&sys, gsl_odeiv2_step_rk8pd, o.h_init, o.atol, o.rtol, 1.0, 0.0);
  std::vector<double> y = s.initial_state();
  double t = 0, h = o.h_init;
  for (double target : grid) {
    while (t < target) {
      if (gsl_odeiv2_evolve_apply(d->e, d->c, d->s, &sys, &t, target, &h, y.data()) != GSL_SUCCESS) {
        gsl_odeiv2_driver_free(d);
        return {};
      }
      ++r.steps;
    }
    r.samples.push_back(y);
  }
  r.failed = d->e->failed_steps;
  gsl_odeiv2_driver_free(d);
  return r;
}

inline Steps native_rk8pd(const System& s, const std::vector<double>& grid, const IntegratorOptions& o) {
  Steps r;
  const IntegrationResult ir = integrate(s, s.initial_state(), 0.0, grid, o, [&](double, std::span<const double> y) {
    r.samples.emplace_back(y.begin(), y.end());
  });
  if (ir.status != IntegrationStatus::success) r.samples.clear();
  r.steps = ir.counters.steps;
  r.failed = ir.counters.failed_steps;
  r.rhs = ir.counters.rhs_evaluations;
  return r;
}

}  // namespace rbcstab::testing
