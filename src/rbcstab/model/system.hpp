#pragma once
// A model level as an ODE operator y' = F(t, y) on a real state, with the structure every level
// shares: F = M(mu) y + s(t) where a single scalar multiplier mu (the tension sigma, or the l = 2
// growth rate in the reduced form) enforces constant excess area. Hence the Jacobian is
// J = M + v w^T with M block diagonal (1x1 and 2x2 rotation blocks) and v w^T of rank one.
#include <complex>
#include <cstddef>
#include <memory>
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
  static constexpr EnumName<ModelLevel> entries[] = {
      {ModelLevel::automatic, "auto"}, {ModelLevel::full, "full"}, {ModelLevel::modal, "modal"},
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

class System {
 public:
  virtual ~System() = default;
  virtual ModelLevel level() const = 0;
  virtual std::size_t dimension() const = 0;
  virtual int L() const = 0;
  virtual void rhs(double t, std::span<const double> y, std::span<double> dydt) const = 0;
  // Fills J = M + v w^T and dF/dt at (t, y).
  virtual void jacobian(double t, std::span<const double> y, StructuredJacobian& J,
                        std::span<double> dfdt) const = 0;
  virtual Observation observe(double t, std::span<const double> y) const = 0;
  // The state the system was built from, and the amplitudes f_{l,m}(t) rebuilt from any state.
  virtual std::vector<double> initial_state() const = 0;
  virtual ModeAmplitudes amplitudes(double t, std::span<const double> y) const = 0;
  // The Rosenbrock stepper's linear solver. Default: jacobian() + StructuredJacobian::solve_shifted
  // (O(n)); systems without a structured Jacobian of their own (the variational system) override it.
  virtual std::unique_ptr<ShiftedSolver> make_shifted_solver() const;
};

}  // namespace rbcstab
