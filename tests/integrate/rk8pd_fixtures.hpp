#pragma once
// The rk8pd stepper's oracle, for its tests and benchmark: GSL's own rk8pd on a system's full state.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <span>
#include <vector>

#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/system.hpp"

namespace rbcstab::testing {

// A system as it is, minus its compact form: integrate() then steps the full state.
class FullState final : public System {
 public:
  explicit FullState(const System& s) : s_(s) {}
  ModelLevel level() const override { return s_.level(); }
  std::size_t dimension() const override { return s_.dimension(); }
  int L() const override { return s_.L(); }
  void rhs(double t, std::span<const double> y, std::span<double> d) const override { s_.rhs(t, y, d); }
  void jacobian(double t, std::span<const double> y, StructuredJacobian& J, std::span<double> d) const override {
    s_.jacobian(t, y, J, d);
  }
  Observation observe(double t, std::span<const double> y) const override { return s_.observe(t, y); }
  std::vector<double> initial_state() const override { return s_.initial_state(); }
  ModeAmplitudes amplitudes(double t, std::span<const double> y) const override { return s_.amplitudes(t, y); }

 private:
  const System& s_;
};

struct Steps {
  std::vector<std::vector<double>> samples;  // y at each grid time (none if the run failed)
  std::size_t steps = 0, failed = 0;
};

inline int gsl_f(double t, const double y[], double dydt[], void* params) {
  const auto* s = static_cast<const System*>(params);
  s->rhs(t, {y, s->dimension()}, {dydt, s->dimension()});
  return GSL_SUCCESS;
}

// GSL's rk8pd with the standard control (a_y = 1, a_dydt = 0) through the grid, as integrate() drove it.
inline Steps gsl_rk8pd(const System& s, const std::vector<double>& grid, const IntegratorOptions& o) {
  gsl_odeiv2_system sys{gsl_f, nullptr, s.dimension(), const_cast<System*>(&s)};
  gsl_odeiv2_driver* d =
      gsl_odeiv2_driver_alloc_standard_new(&sys, gsl_odeiv2_step_rk8pd, o.h_init, o.atol, o.rtol, 1.0, 0.0);
  Steps r;
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
  const IntegrationResult ir = integrate(s, s.initial_state(), 0.0, grid, o,
                                         [&](double, std::span<const double> y) { r.samples.emplace_back(y.begin(), y.end()); });
  if (ir.status != IntegrationStatus::success) r.samples.clear();
  r.steps = ir.counters.steps;
  r.failed = ir.counters.failed_steps;
  return r;
}

}  // namespace rbcstab::testing
