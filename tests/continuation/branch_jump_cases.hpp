#pragma once
// The large-S out-of-plane equilibrium branch continued in Lambda: one run of the grid (level, S,
// start Lambda0, max step) and its comparison, point by point, with the reference at the same Lambda: the
// closed-form state of the stable branch (the reduced state; the modal one is it with v = a_l = 0; the full one
// is it as x_{2,0} = -w, x_{2,2} = z with every other coordinate 0) and the spectrum there. At the modal and full
// levels the closed form holds on the whole branch, past the l >= 3 onsets too: with delta = 0 and no
// rest_delta_l nothing drives the l >= 3 modes (nor v, nor m != 0 of l >= 3), so the ellipsoidal states are an
// invariant set of the equations and of Newton; past an onset they are the same equilibria, unstable. The closed form
// is the oracle rather than a small-step run because a small step is exactly what can jump here (at S = 1e6 the
// branches pass within ~3e-3 of each other).
#include <cmath>
#include <cstddef>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/equilibrium.hpp"
#include "rbcstab/continuation/full_equilibrium.hpp"
#include "rbcstab/continuation/modal_equilibrium.hpp"
#include "rbcstab/core/constants.hpp"

namespace rbcstab::jump_cases {

enum class Level { reduced, modal, full };

struct Case {
  Level level = Level::reduced;
  double S = 1000;
  double Lambda0 = 0.5;  // the start
  double max_step = 0.5;
  bool guard = true;  // ContinuationOptions::confirm_special_points
};

struct Outcome {
  Branch branch;
  std::size_t wrong_state = 0;      // points off the reference state by more than 1e-8 (max norm)
  std::size_t wrong_stability = 0;  // points whose unstable count differs from the reference's
  std::string first;                // the first wrong point, for the message
  // Followed its branch, or said it could not: never a different branch called completed.
  bool honest() const {
    return (wrong_state == 0 && wrong_stability == 0) || branch.status == ContinuationStatus::branch_lost;
  }
  bool followed() const { return wrong_state == 0 && wrong_stability == 0; }
};

// The reported runs: Lambda over [0.01, 10], moved through Delta at fixed lambda (Lambda = 3 sqrt(Delta)),
// Delta0 = 1e-5 (Delta stays in [Delta0, 4 pi)), beta = 0 (out of plane); C sets S (S ~ C at fixed Delta0).
inline Scene scene_of(const Case& c) {
  Scene s;
  s.beta = 0;
  s.parameters.lambda = (3 * 8 * std::sqrt(30 * kPi) - 32) / 23;  // Lambda / sqrt(Delta) = 3
  s.parameters.Delta0 = 1e-5;
  s.parameters.Delta = (c.Lambda0 / 3) * (c.Lambda0 / 3);
  s.parameters.B = 2;
  s.L = 4;
  s.delta = 0;  // Delta reaches 1.1e-5: no l >= 3 perturbation (equilibria do not read it)
  s.parameters.C = c.S / std::sqrt(15 * kPi / (2 * s.parameters.Delta0));
  return s;
}

inline constexpr double kLambdaMin = 0.01, kLambdaMax = 10;

inline std::unique_ptr<ContinuationProblem> problem_of(const Case& c) {
  const Scene scene = scene_of(c);
  if (c.level == Level::reduced)
    return std::make_unique<ReducedEquilibriumProblem>(scene, ContinuationParameter::Lambda);
  if (c.level == Level::modal) return std::make_unique<ModalEquilibriumProblem>(scene, ContinuationParameter::Lambda);
  return std::make_unique<FullEquilibriumProblem>(scene, ContinuationParameter::Lambda);
}

// The stable branch's state at Lambda = p in the level's coordinates (n of them).
inline Eigen::VectorXd reference_state(const Case& c, Eigen::Index n, double p) {
  // The closed form (docs/theory.md): u = r^2 the smaller root of Lambda^2 u^2 - b u + 1, b = 1 + Lambda^2 +
  // S^-2, w = sqrt(1 - u) > 0, sin Psi = sqrt(1 - Lambda^2 u), cos Psi = Lambda r; z = r e^{-i Psi}; modes
  // l >= 3 and v at 0. 1 - u and 1 - Lambda^2 u from t = sqrt(D) - |1 - Lambda^2| without cancellation (both
  // are ~S^-2 on one side of Lambda = 1), as in out_of_plane_equilibrium — which would do, but it validates a
  // default Scene, whose delta = 1e-3 exceeds Delta below Lambda = 0.095 here.
  const double L2 = p * p, s2 = 1 / (c.S * c.S), e = std::abs(1 - L2), q = s2 * (2 + 2 * L2 + s2);
  const double sqrtD = std::sqrt(e * e + q), t = sqrtD + e > 0 ? q / (sqrtD + e) : 0.0;
  const double den = 1 + L2 + s2 + sqrtD, small = (s2 + t) / den, large = (2 * e + s2 + t) / den;
  const double r = std::sqrt(2 / den), w = std::sqrt(L2 <= 1 ? small : large);
  const double Psi = std::atan2(std::sqrt(L2 <= 1 ? large : small), p * r);
  // (Through a std::vector: GCC 12 flags writes into a fresh dynamic Eigen vector as null dereferences.)
  std::vector<double> x = {r * std::cos(Psi), -r * std::sin(Psi), w};
  if (c.level == Level::full) x = {-w, 0.0, 0.0, r * std::cos(Psi), -r * std::sin(Psi)};  // index(l, m)
  x.resize(static_cast<std::size_t>(n), 0.0);
  return Eigen::Map<const Eigen::VectorXd>(x.data(), n);
}

inline Outcome run_case(const Case& c) {
  const std::unique_ptr<ContinuationProblem> problem = problem_of(c);
  const ContinuationProblem& pr = *problem;
  auto reference = [&](double p) { return reference_state(c, pr.dimension(), p); };
  ContinuationOptions o;
  o.p_min = kLambdaMin;
  o.p_max = kLambdaMax;
  o.direction = Direction::both;
  o.max_step = c.max_step;
  o.initial_step = std::min(1e-2, c.max_step);
  o.confirm_special_points = c.guard;
  Outcome out;
  out.branch = continue_branch(pr, reference(c.Lambda0), c.Lambda0, o);
  for (std::size_t i = 0; i < out.branch.points.size(); ++i) {
    const BranchPoint& pt = out.branch.points[i];
    const Eigen::VectorXd x = reference(pt.p);
    const double d = (pt.x - x).lpNorm<Eigen::Infinity>();
    const int n = count_unstable(pr.spectrum(x, pt.p), pr.stability_kind(), o.stability_tol);
    const bool state_ok = d <= 1e-8, stability_ok = n == pt.n_unstable;
    out.wrong_state += !state_ok;
    out.wrong_stability += !stability_ok;
    if ((!state_ok || !stability_ok) && out.first.empty()) {
      std::ostringstream os;
      os << "point " << i << " at Lambda = " << pt.p << ": off the reference by " << d << ", unstable " << pt.n_unstable
         << " (reference " << n << ")";
      out.first = os.str();
    }
  }
  return out;
}

inline const char* level_name(Level l) {
  return l == Level::reduced ? "reduced" : l == Level::modal ? "modal" : "full";
}

inline std::string describe(const Case& c) {
  std::ostringstream os;
  os << level_name(c.level) << " S = " << c.S << " Lambda0 = " << c.Lambda0 << " max_step = " << c.max_step;
  return os.str();
}

}  // namespace rbcstab::jump_cases
