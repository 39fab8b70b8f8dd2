#pragma once
// Periodic orbits of the modal model under the in-plane forcing of a rotating rest
// shape, as a ForcedSystem for PeriodicOrbitProblem (multiple shooting, Floquet multipliers).
//
// Coordinates: those of modal_equilibrium.hpp, x = (Re z, Im z, w, Re v~, Im v~, a_3, ..., a_L) scaled
// by the total excess area Delta (|x|^2 = 1), except that v~ = v e^{-it/2} is taken in the frame
// co-rotating with the m = 1 forcing. In the lab frame the rest shape's m = 1 content drives
// v' = (i/2 + Y_2) v + kappa v0 e^{it/2}, period 4 pi; in the co-rotating frame
//   v~' = Y_2 v~ + kappa v0,
// while |v~| = |v| and Re(conj(v) v0 e^{it/2}) = Re(conj(v~) v0), so sigma is unchanged and the
// whole system is 2 pi-periodic for every beta:
//   z' = (i + Y_2) z - i/Lambda + kappa z0 e^{it},  w' = Y_2 w + kappa w0,  v~' = Y_2 v~ + kappa v0,
//   a_l' = Y_l a_l,  Y_l = Upsilon_l(sigma),  sigma from x.x' = 0 (modal_dynamics).
// (z0, w0, v0) is the rest shape's unit direction (z0 = sqrt(2) g22, w0 = -g20, v0 = sqrt(2) g21,
// normalised) and kappa = 1/(Lambda S). x.x' = 0, so |x|^2 is conserved (conserves_norm).
// A physical orbit with v~ != 0 has period 4 pi in the lab frame (v flips sign over 2 pi).
//
// Floquet multipliers: on an orbit with a_l = 0 the a_l direction decouples, da_l' = Y_l da_l, with
// multiplier exp(int_0^{2 pi} Upsilon_l(sigma(t)) dt) (tested against the reduced orbit's sigma(t)).
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/continuation/modal_equilibrium.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/model/modal_model.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

// The scene whose parameters.Delta is the total excess area of `simulated`'s initial shape
// (Delta_2(0) + sum_l delta_l): the orbit problem of a simulation of `simulated` (the modal model's
// dynamics depend on Delta only through the initial shape; the regular coordinates need the total).
Scene total_area_scene(const Scene& simulated);

class ModalForcedSystem final : public ForcedSystem {
 public:
  // parameters.Delta is the total excess area; scene.L >= 3 modes; any beta.
  ModalForcedSystem(const Scene& scene, ContinuationParameter free);
  Eigen::Index dimension() const override { return 5 + (L_ - 2); }
  void rhs(double t, std::span<const double> x, double p, std::span<double> f) const override;
  void jacobian(double t, std::span<const double> x, double p, Eigen::MatrixXd& J) const override;
  // Exact in x and t: f depends on p only through the coefficients (Upsilon_l(0), slopes, 1/Lambda,
  // kappa), whose p-slopes are central differences of constants (no noise in the sensitivity equation),
  // and, for beta, through the rest shape's direction, differentiated in closed form.
  void parameter_derivative(double t, std::span<const double> x, double p, std::span<double> fp) const override;
  bool conserves_norm() const override { return true; }
  std::string parameter_name() const override { return to_string(free_); }

  int L() const { return L_; }
  double start_parameter() const { return get_parameter(scene_, free_); }
  const Scene& scene() const { return scene_; }
  // The forcing h(t) at p (layout of x).
  Eigen::VectorXd forcing(double t, double p) const;
  const ModalCoefficients& coefficients(double p) const;  // cached (a few values: p and p +- h)

  // sigma, r, Psi (of (z, w)) and Delta_l = Delta a_l^2 (Delta_2 = Delta |(z, w, v)|^2) at (t, x).
  ModalState observe(double t, const Eigen::VectorXd& x, double p) const;
  // Conversions to and from the ModalModel state (f20, Re f21, Im f21, Re f22, Im f22, ln Delta_l for
  // its active modes) at time t. to_ requires every a_l != 0 (the modal model then carries them all).
  std::vector<double> to_modal_model_state(double t, const Eigen::VectorXd& x, double p) const;
  Eigen::VectorXd from_modal_model_state(const ModalModel& m, double t, std::span<const double> y, double p) const;

  // The state at t = 2 pi k >= T of a ModalModel simulation of `simulated` (a start for the shooting
  // Newton on an attracting orbit; use this system built from total_area_scene(simulated)). poll: the
  // integration's IntegratorOptions::poll (OrbitOptions::poll). A simulation that fails (an input that overflows)
  // throws InvalidArgument("T", ...), or with `failure` given sets *failure to its reason and returns NaNs.
  Eigen::VectorXd relaxed_state(const Scene& simulated, double T, const std::function<void()>& poll = {},
                                double rtol = 1e-11, std::string* failure = nullptr) const;

 private:
  struct Direction {
    std::complex<double> z0, v0;  // rest shape's unit direction (with w0)
    double w0 = 0;
  };
  struct Slopes {
    std::vector<double> dups0, dslope;  // index l - 2
    double dinvL = 0, dkappa = 0;
    Direction dg;  // beta only: the rest direction's slope
  };
  static Direction direction_of(const Scene& scene);
  const Direction& direction(double p) const;  // the scene's, or rebuilt per value when beta is free
  const Slopes& slopes(double p) const;
  double kappa(double p) const { return coefficients(p).parameters.inv_Lambda_S(); }
  Eigen::VectorXd forcing_with(double t, double inv_Lambda, double kappa, const Direction& d) const;
  Scene scene_;
  ContinuationParameter free_;
  int L_;
  Direction direction_;
  mutable std::map<double, ModalCoefficients> cache_;
  mutable std::map<double, Slopes> slopes_;
  mutable std::map<double, Direction> directions_;
};

}  // namespace rbcstab
