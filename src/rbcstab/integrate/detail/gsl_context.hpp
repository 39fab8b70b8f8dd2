#pragma once
// Private: what the GSL callbacks see through gsl_odeiv2_system::params.
#include <gsl/gsl_odeiv2.h>

#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/structured_jacobian.hpp"

namespace rbcstab::detail {

struct GslContext {
  const System* system = nullptr;
  const CompactForm* form = nullptr;  // stepped instead of the system's state when set (rk8pd only)
  IntegrationCounters* counters = nullptr;
  StructuredJacobian jacobian;    // scratch for the dense-Jacobian callback
  std::size_t nonfinite_rhs = 0;  // trial states where F was not finite (each rejects its trial step)
  double nonfinite_t = 0;         // time of the last such trial state
};

// The linearly implicit Rosenbrock stepper, as a GSL step type.
const gsl_odeiv2_step_type* rosenbrock_step_type();

}  // namespace rbcstab::detail
