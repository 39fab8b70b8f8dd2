#pragma once
// A model level as an ODE operator y' = F(t, y) on a real state, with the structure every level
// shares: F = M(mu) y + s(t) where a single scalar multiplier mu (the tension sigma, or the l = 2
// growth rate in the reduced form) enforces constant excess area. Hence the Jacobian is
// J = M + v w^T with M block diagonal (1x1 and 2x2 rotation blocks) and v w^T of rank one.
#include <complex>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/model/amplitudes.hpp"
#include "rbcstab/model/structured_jacobian.hpp"

namespace rbcstab {

enum class ModelLevel { automatic, full, modal, reduced };
template <>
struct EnumTable<ModelLevel> {
  static constexpr EnumName<ModelLevel> entries[] = {{ModelLevel::automatic, "auto"},
                                                     {ModelLevel::full, "full"},
                                                     {ModelLevel::modal, "modal"},
                                                     {ModelLevel::reduced, "reduced"}};
};
// Throws InvalidArgument("model", ...) naming the allowed levels.
inline ModelLevel model_level_from_string(std::string_view name) { return from_string<ModelLevel>(name, "model"); }

// What every level reports at a state: the excess area per mode and the tension.
struct Observation {
  std::vector<double> Delta_l;  // index l - 2, l = 2..L
  double sigma = 0;             // homogeneous membrane tension sigma(t)
  std::complex<double> f22;     // f_{2,2}: r and Psi are read from it
  double Delta2 = 0;            // excess area held by l = 2 (normalises r)

  // The paper's (r, Psi) of the l = 2 ellipsoid: r = |f_{2,2}| sqrt(4 / Delta_2) in [0, 1] (0 when l = 2 holds
  // no area), Psi = -arg f_{2,2} in (-pi, pi] (pi for the in-plane start, as the paper).
  double r() const;
  double Psi() const;
  // -arg f_{2,2} on the branch nearest to `previous`: Psi followed continuously along a trajectory.
  double Psi_near(double previous) const;
};

// The linear algebra of a linearly implicit stepper at one point (t, y): solves (I - c J) x = b with
// J = dF/dy there. Made per integration by System::make_shifted_solver, so it may keep scratch and the
// last linearisation without any state shared between threads.
class ShiftedSolver {
 public:
  virtual ~ShiftedSolver() = default;
  // Evaluates J and dF/dt at (t, y); the solves below use this J until the next call.
  virtual void linearize(double t, std::span<const double> y, std::span<double> dfdt) = 0;
  // (I - c J) x = b; false if the shifted matrix is singular to working precision.
  virtual bool solve(double c, std::span<const double> b, std::span<double> x) = 0;
};

// The same flow on fewer unknowns x: some components of the state y kept as they are, the others following
// integrals, each y_k' = scale_k (g_i - pivot_k) for the integrand g_i of integral x_i = int (g_i - reference_i),
//   y_k = offset_k + scale_k (x_i + (reference_i - pivot_k) tau),   i = source_k,
// with tau = x[clock] the time since the integrals started (tau' = 1). A kept component has scale 1 and offset,
// pivot and reference 0. A stepper may then step x and still control the error of each y_k,
// e_{y,k} = scale_k e_{x,i} (integrate/integrator.hpp). The modal level's u_l = ln Delta_l, with
// u_l' = 2 Upsilon_l' (sigma - sigma_l^c), all follow from one integral of sigma.
//
// Rounding: tau is stepped like every other component (the rounded t - t0 would add ulp(t) per step), and a
// stepper restarts the integrals after every step (rebase) with each reference set to its integrand's value at
// the step's start (center), so that an integral holds one step's worth of a small difference, reference - pivot
// is exact near the pivot (as sigma - sigma_l^c is in y_k'), and the steps depend on the state alone (a run
// restarted from a step's end takes the same steps as one that goes on).
struct CompactForm {
  std::vector<double> x0;           // x where the integrals start (each of them 0)
  std::vector<bool> integral;       // per component of x: an integral (the clock included), restarted by rebase()
  std::vector<double> reference;    // per component of x: subtracted from its integrand (0 unless an integral)
  std::size_t clock = 0;            // the component of x that is tau
  std::vector<std::size_t> source;  // per component of y
  std::vector<double> scale, offset, pivot;
  double y(std::size_t k, std::span<const double> x) const {
    const std::size_t i = source[k];
    return offset[k] + scale[k] * (x[i] + (reference[i] - pivot[k]) * x[clock]);
  }
  // y_k' given x' (dx).
  double rate(std::size_t k, std::span<const double> dx) const {
    const std::size_t i = source[k];
    return scale[k] * (dx[i] + (reference[i] - pivot[k]) * dx[clock]);
  }
  // Building a form: a new unknown of x (its index), a new component of y following x[source], and a component
  // of y kept as it is (both appended).
  std::size_t add_unknown(double value, bool is_integral);
  void add_component(std::size_t source_index, double scale_k, double offset_k, double pivot_k);
  void keep(double value) { add_component(add_unknown(value, false), 1.0, 0.0, 0.0); }
  void expand(std::span<const double> x, std::span<double> y) const;
  // Restarts the integrals at 0, the offsets taking the values reached and the references back at 0.
  void rebase(std::span<double> x);
  // At a step's start, given x' there with references 0: each reference becomes its integrand's value and the
  // integral's rate 0.
  void center(std::span<double> rate);
};

class System {
 public:
  virtual ~System() = default;
  virtual ModelLevel level() const = 0;
  virtual std::size_t dimension() const = 0;
  virtual int L() const = 0;
  virtual void rhs(double t, std::span<const double> y, std::span<double> dydt) const = 0;
  // Fills J = M + v w^T and dF/dt at (t, y).
  virtual void jacobian(double t, std::span<const double> y, StructuredJacobian& J, std::span<double> dfdt) const = 0;
  virtual Observation observe(double t, std::span<const double> y) const = 0;
  // The state the system was built from, and the amplitudes f_{l,m}(t) rebuilt from any state.
  virtual std::vector<double> initial_state() const = 0;
  virtual ModeAmplitudes amplitudes(double t, std::span<const double> y) const = 0;
  // The Rosenbrock stepper's linear solver. Default: jacobian() + StructuredJacobian::solve_shifted
  // (O(n)); systems without a structured Jacobian of their own (the variational system) override it.
  virtual std::unique_ptr<ShiftedSolver> make_shifted_solver() const;
  // The compact form through y0 when the level has one smaller than y; none by default.
  virtual std::optional<CompactForm> compact_form(std::span<const double> y0) const;
  // x' at (t, x) for a form this system made (compact_form), the clock's 1 included. Throws std::logic_error for
  // a system without one.
  virtual void compact_rhs(double t, std::span<const double> x, const CompactForm& form, std::span<double> dxdt) const;
};

}  // namespace rbcstab
