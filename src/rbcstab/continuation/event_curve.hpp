#pragma once
// Two-parameter continuation of an event: the curve in (p1, p2) along which a smooth function of the
// solution vanishes (a UZ point of a one-parameter branch, continued in a second parameter). Unknowns
// X = (x, p1, a), free parameter p2, equations
//   F(x, p1, p2) = 0   (the two-parameter problem, n equations)
//   G(x, p1, a, p2) = 0 (the event, m + 1 equations in its m auxiliary unknowns a),
// so the curve is one more branch of the same engine (as the fold and Hopf curves).
//
// What the library needs from an event (CurveEvent):
//   - G is C^2 in (x, p1, a, p2) near the curve (Newton converges quadratically, the engine's central
//     differences in p2 are accurate), and is computed to well below the Newton tolerance: no sampled
//     minima, no discrete choices (a branch, a segment, a winding number) that can change between
//     arguments closer than a difference step;
//   - the zero is regular: [G_x G_p1 G_a] restricted to the branch's tangent (x'(p1), 1) and the a
//     directions is invertible ((m + 1) x (m + 1)), i.e. along the one-parameter branch the event
//     crosses zero transversally (a simple UZ);
//   - the auxiliary unknowns at the starting UZ point (auxiliary_start).
// A scalar event g(x, p1, p2) with these properties is m = 0 (ScalarCurveEvent); the swinging <->
// tumbling transition of an orbit is OrbitPassageEvent (m = 1, see there why not the UZ function).
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/fold_curve.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/orbit_two_parameter.hpp"

namespace rbcstab {

class CurveEvent {
 public:
  virtual ~CurveEvent() = default;
  virtual std::string name() const = 0;
  virtual Eigen::Index auxiliary_dimension() const { return 0; }  // m
  // G (m + 1 values).
  virtual void residual(const Eigen::VectorXd& x, double p1, const Eigen::VectorXd& a, double p2,
                        Eigen::VectorXd& G) const = 0;
  // D = [dG/dx, dG/dp1, dG/da] ((m + 1) x (n + 1 + m)). Default: central differences of residual
  // (step cbrt(eps)(1 + |v|)).
  virtual void jacobian(const Eigen::VectorXd& x, double p1, const Eigen::VectorXd& a, double p2,
                        Eigen::MatrixXd& D) const;
  // a at a solution (x, p1, p2) where the event is (nearly) zero: the start of the curve. Throws
  // InvalidArgument("event", ...) when the point is not one of the event's zeros.
  virtual Eigen::VectorXd auxiliary_start(const Eigen::VectorXd& x, double p1, double p2) const = 0;
};

// A scalar event g(x, p1, p2) (no auxiliary unknown), e.g. a UserEvent of the one-parameter problem at
// each p2. g must be smooth (CurveEvent); auxiliary_start accepts any start.
class ScalarCurveEvent final : public CurveEvent {
 public:
  using Function = std::function<double(const Eigen::VectorXd& x, double p1, double p2)>;
  ScalarCurveEvent(std::string name, Function g);
  std::string name() const override { return name_; }
  void residual(const Eigen::VectorXd& x, double p1, const Eigen::VectorXd& a, double p2,
                Eigen::VectorXd& G) const override;
  Eigen::VectorXd auxiliary_start(const Eigen::VectorXd&, double, double) const override { return {}; }

 private:
  std::string name_;
  Function g_;
};

// The swinging <-> tumbling transition of a forced orbit (components 0, 1 = Re z, Im z: the reduced
// system and the modal model alike) as a smooth event: the orbit passes through z = 0 at some time t*,
//   G(X, p1, t*, p2) = (Re z(t*), Im z(t*)),   one auxiliary unknown t* (the passage time),
// z(t*) integrated from the shooting state of t*'s segment (PeriodicOrbitProblem::point_at), with the
// exact derivatives of the variational equations: d z/d x_j = rows of Phi(t*, t_j), d z/d t* = f,
// d z/d p1 = the sensitivity. Two equations for one extra unknown: the transition is codimension one.
// Its zero is regular where the orbit moves through z = 0 (z' != 0) and the branch crosses it
// transversally.
//
// Why not the one-parameter UZ function s = +-r_min (transition_event) as a scalar event: r_min is the
// minimum of sampled |z(t)| refined by a secant, and its sign is the winding number read from an angle
// whose integration is singular at z = 0, exactly where every curve point lies (when that integration
// fails, the angle is read from samples, whose chords misread passages within ~1e-5 of z = 0). Near the
// transition it is nevertheless smooth to ~1e-12 (measured; as a ScalarCurveEvent it gives the same curve,
// tests/continuation/event_curve_test.cpp), but each evaluation is a dense pass over the period and its
// Jacobian row 2 (n N + 1) of them (measured: 25x the CPU time of this event on a 28-point curve). With the passage
// time t* as an unknown the event is a plain smooth function of the unknowns with an exact derivative, needs no winding
// number (at a zero both components vanish) and costs one integration over part of a segment.
class OrbitPassageEvent final : public CurveEvent {
 public:
  explicit OrbitPassageEvent(const OrbitTwoParameterProblem& base, std::string name = std::string(kTransitionEventName))
      : base_(base), name_(std::move(name)) {}
  std::string name() const override { return name_; }
  Eigen::Index auxiliary_dimension() const override { return 1; }
  void residual(const Eigen::VectorXd& X, double p1, const Eigen::VectorXd& a, double p2,
                Eigen::VectorXd& G) const override;
  void jacobian(const Eigen::VectorXd& X, double p1, const Eigen::VectorXd& a, double p2,
                Eigen::MatrixXd& D) const override;
  // t* = the time of r_min (OrbitSummary::t_r_min); throws InvalidArgument("event", ...) unless
  // r_min < max_start_distance (the start is a UZ of the transition, r_min ~ 1e-8 or less).
  Eigen::VectorXd auxiliary_start(const Eigen::VectorXd& X, double p1, double p2) const override;
  static constexpr double max_start_distance = 1e-4;

 private:
  const OrbitTwoParameterProblem& base_;
  std::string name_;
};

// The event's curve from a located UZ point of SliceProblem(base, p2) (the event's zero at p2).
class EventCurveProblem final : public ContinuationProblem {
 public:
  // Throws InvalidArgument("uz", ...) unless uz is a located point of base's dimension, and whatever
  // event.auxiliary_start throws. base and event must outlive the problem.
  EventCurveProblem(const TwoParameterProblem& base, const CurveEvent& event, const SpecialPoint& uz, double p2);
  Eigen::Index dimension() const override { return n_ + 1 + m_; }
  void residual(const Eigen::VectorXd& X, double p2, Eigen::VectorXd& R) const override;
  // [F_x F_p1 0; D]: the base problem's Jacobian (analytic where it has one) and the event's rows.
  void jacobian(const Eigen::VectorXd& X, double p2, Eigen::MatrixXd& J) const override;
  // The base problem's spectrum and stability (orbits: Floquet multipliers).
  Eigen::VectorXcd spectrum(const Eigen::VectorXd& X, double p2) const override;
  // The base problem's, as spectrum (not the curve system's Jacobian, whose eigenvalues are not these).
  CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& X, double p2, bool refine) const override;
  StabilityKind stability_kind() const override { return base_.stability_kind(); }
  std::string parameter_name() const override { return base_.name2(); }
  std::vector<std::string> parameter_names() const override { return {base_.name1(), base_.name2()}; }
  std::vector<double> parameter_values(const Eigen::VectorXd& X, double p2) const override { return {X[n_], p2}; }
  const Eigen::VectorXd& start() const { return start_; }  // (x, p1, a) at the UZ point
  Eigen::VectorXd auxiliary(const Eigen::VectorXd& X) const { return X.tail(m_); }

 private:
  const TwoParameterProblem& base_;
  const CurveEvent& event_;
  Eigen::Index n_, m_;
  Eigen::VectorXd start_;
};

}  // namespace rbcstab
