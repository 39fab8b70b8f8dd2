#pragma once
// Time integration of a model level (adaptive steppers: rk8pd of its own, the others GSL odeiv2's; user output
// grid, counters). rk8pd steps a system's compact form when it has one (System::compact_form).
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/model/system.hpp"

namespace rbcstab {

enum class Stepper {
  rk8pd,       // explicit Prince-Dormand 8(7) (detail/prince_dormand.hpp): the default for non-stiff levels
  rkck,        // explicit Cash-Karp 4(5)
  rkf45,       // explicit Runge-Kutta-Fehlberg 4(5)
  msadams,     // explicit/implicit Adams multistep (functional iteration)
  rosenbrock,  // linearly implicit Rosenbrock 4(3) (Shampine's RODAS-type GRK4T) using J = M + v w^T: O(n) solves
  msbdf,       // GSL's BDF with dense analytic Jacobian
  bsimp,       // GSL's implicit Bulirsch-Stoer with dense analytic Jacobian
  rk4imp,      // GSL's implicit Gauss 4th order with dense analytic Jacobian
};
template <>
struct EnumTable<Stepper> {
  static constexpr EnumName<Stepper> entries[] = {{Stepper::rk8pd, "rk8pd"},           {Stepper::rkck, "rkck"},
                                                  {Stepper::rkf45, "rkf45"},           {Stepper::msadams, "msadams"},
                                                  {Stepper::rosenbrock, "rosenbrock"}, {Stepper::msbdf, "msbdf"},
                                                  {Stepper::bsimp, "bsimp"},           {Stepper::rk4imp, "rk4imp"}};
};
// Throws InvalidArgument("stepper", ...) naming the allowed steppers.
inline Stepper stepper_from_string(std::string_view name) { return from_string<Stepper>(name, "stepper"); }
inline const std::vector<std::string>& stepper_names() { return enum_names<Stepper>(); }
bool is_implicit(Stepper s);
// The dense n x n matrices a stepper keeps (measured peak memory at n = 874: msbdf and bsimp 2, rk4imp 5, its
// Newton matrix being 2n x 2n); 0 for the explicit steppers and rosenbrock (O(n) structured solves).
int dense_matrices(Stepper s);
// Dense steppers are allowed up to this dimension: 2 matrices of 72 MB (5 for rk4imp), and one LU factorisation
// per step that stays within seconds. Throws InvalidArgument("stepper", ...) with the matrices' memory and the
// limit for a larger system; `system` names it in the message ("the full level at L = 40").
constexpr std::size_t kMaxDenseDimension = 3000;
void require_dense_dimension(Stepper s, std::size_t n, const std::string& system);

struct IntegratorOptions {
  Stepper stepper = Stepper::rk8pd;    // rk8pd: cheapest per digit for the modal level (docs/benchmarks.md)
  double rtol = 1e-8;                  // relative tolerance of the local error control
  double atol = 1e-12;                 // absolute tolerance (for the modal level: on ln Delta_l too)
  double h_init = 1e-3;                // first trial step; adapted at once
  double h_min = 1e-13;                // a step below this ends the run as step_size_underflow
  std::size_t max_steps = 20'000'000;  // bounds the work: a run never hangs
  double max_seconds = 0;              // wall-clock budget; 0 = none
  // Called every few accepted steps so that a front end can abandon a run (the Python module raises
  // KeyboardInterrupt through it): it may throw, and the exception leaves the integrator. Empty: never.
  std::function<void()> poll{};
  void validate() const;  // throws InvalidArgument naming the field
};

enum class IntegrationStatus { success, step_size_underflow, non_finite_state, step_limit, time_limit, solver_error };
template <>
struct EnumTable<IntegrationStatus> {
  static constexpr EnumName<IntegrationStatus> entries[] = {
      {IntegrationStatus::success, "success"},
      {IntegrationStatus::step_size_underflow, "step_size_underflow"},
      {IntegrationStatus::non_finite_state, "non_finite_state"},
      {IntegrationStatus::step_limit, "step_limit"},
      {IntegrationStatus::time_limit, "time_limit"},
      {IntegrationStatus::solver_error, "solver_error"}};
};

struct IntegrationCounters {
  std::size_t steps = 0;         // accepted steps
  std::size_t failed_steps = 0;  // rejected trial steps
  std::size_t rhs_evaluations = 0;
  std::size_t jacobian_evaluations = 0;
  IntegrationCounters& operator+=(const IntegrationCounters& o) {
    steps += o.steps;
    failed_steps += o.failed_steps;
    rhs_evaluations += o.rhs_evaluations;
    jacobian_evaluations += o.jacobian_evaluations;
    return *this;
  }
};

struct IntegrationResult {
  IntegrationStatus status = IntegrationStatus::success;
  std::string reason;  // empty on success
  double t_reached = 0;
  bool stopped = false;   // the stop condition ended the run at t_reached (status success)
  std::vector<double> y;  // state at t_reached
  IntegrationCounters counters;
  double seconds = 0;
};

using StateObserver = std::function<void(double t, std::span<const double> y)>;
// Asked after each accepted step (after on_step): true ends the run there, with status success.
using StopCondition = std::function<bool(double t, std::span<const double> y)>;

// Integrates y' = F(t, y) from (t0, y0) through the increasing times in grid (each > t0 or equal
// to it), calling on_sample at each grid time and on_step after each accepted step, until the last
// grid time or until stop says so (IntegrationResult::stopped).
IntegrationResult integrate(const System& system, std::span<const double> y0, double t0, std::span<const double> grid,
                            const IntegratorOptions& options, const StateObserver& on_sample,
                            const StateObserver& on_step = {}, const StopCondition& stop = {});

}  // namespace rbcstab
