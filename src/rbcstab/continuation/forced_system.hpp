#pragma once
// Periodically forced ODEs x' = f(t, x, p) (period 2 pi in t, fixed), whose periodic orbits orbit.hpp
// continues: the small ForcedSystem interface, which the in-plane reduced system (ReducedForcedSystem) and
// the textbook normal forms of the tests implement.
#include <functional>
#include <map>
#include <span>
#include <string>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/model/reduced_model.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

// x' = f(t, x, p), 2 pi-periodic in t. Components 0 and 1 are the plane whose winding classifies
// the orbit (Re z, Im z for the reduced system).
class ForcedSystem {
 public:
  virtual ~ForcedSystem() = default;
  virtual Eigen::Index dimension() const = 0;
  virtual void rhs(double t, std::span<const double> x, double p, std::span<double> f) const = 0;
  // df/dx (n x n).
  virtual void jacobian(double t, std::span<const double> x, double p, Eigen::MatrixXd& J) const = 0;
  // df/dp. Default: central differences of rhs in p. Prefer an analytic one: the rounding noise of
  // the difference (~eps |f| / h) enters the sensitivity equation, whose error control at rtol 1e-12
  // then forces small steps (measured: ~20x slower shooting on the test systems).
  virtual void parameter_derivative(double t, std::span<const double> x, double p, std::span<double> fp) const;
  // f, df/dx and, when fp is not empty, df/dp at one (t, x, p): the variational equations' right-hand side
  // (one call per integration stage). Default: rhs, jacobian and parameter_derivative; a system whose three
  // share work (the forcing phasor, a cached model) overrides it with the same values.
  virtual void flow_terms(double t, std::span<const double> x, double p, std::span<double> f, Eigen::MatrixXd& J,
                          std::span<double> fp) const;
  // True when x . f(t, x, p) = 0 identically (Q = |x|^2 conserved, the reduced system's excess
  // area): the monodromy then has a trivial multiplier 1 and the shooting system is regularised.
  virtual bool conserves_norm() const { return false; }
  virtual std::string parameter_name() const { return "p"; }
};

// The in-plane reduced system (ReducedModel, z0(t) = z0(0) e^{it}) with one free ContinuationParameter.
class ReducedForcedSystem final : public ForcedSystem {
 public:
  ReducedForcedSystem(const Scene& scene, ContinuationParameter free);
  Eigen::Index dimension() const override { return 3; }
  void rhs(double t, std::span<const double> x, double p, std::span<double> f) const override;
  void jacobian(double t, std::span<const double> x, double p, Eigen::MatrixXd& J) const override;
  void parameter_derivative(double t, std::span<const double> x, double p, std::span<double> fp) const override;
  void flow_terms(double t, std::span<const double> x, double p, std::span<double> f, Eigen::MatrixXd& J,
                  std::span<double> fp) const override;
  bool conserves_norm() const override { return true; }
  std::string parameter_name() const override { return to_string(free_); }

  double start_parameter() const { return get_parameter(scene_, free_); }
  // The state after relaxing from the scene's initial shape for T rounded up to a multiple of 2 pi
  // (so it is a state at t = 0 mod 2 pi, a start for the shooting Newton on an attracting orbit). poll:
  // the integration's IntegratorOptions::poll (OrbitOptions::poll).
  Eigen::VectorXd relaxed_state(double T, const std::function<void()>& poll = {}) const;
  const ReducedModel& model(double p) const;  // cached (a few parameter values: p and p +- h)

 private:
  struct Slopes {
    double dinvL = 0, dkappa = 0, kappa = 0;  // d(1/Lambda)/dp, d kappa/dp, kappa at p
    double dz0 = 0, dw0 = 0;                  // beta only: the rest direction's slope (z0 at t = 0)
  };
  Slopes coefficient_slopes(double p) const;
  // df/dp given the forcing direction g = (Re z0(t), Im z0(t), w0) at t (the model's, at p).
  void parameter_derivative(double t, std::span<const double> x, double p, const double g[3],
                            std::span<double> fp) const;
  Scene scene_;
  ContinuationParameter free_;
  InitialState init_;
  mutable std::map<double, ReducedModel> cache_;
  mutable std::map<double, Slopes> slopes_;
};

}  // namespace rbcstab
