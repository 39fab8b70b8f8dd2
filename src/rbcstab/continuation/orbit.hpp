#pragma once
// Periodic orbits of periodically forced ODEs x' = f(t, x, p) (period 2 pi in t, fixed) by multiple
// shooting with variational equations, as a ContinuationProblem with Floquet multipliers
// (stability_kind = multipliers, so the engine's LPC / PD / NS test functions apply).
//
// One code path for every forced system (forced_system.hpp): the in-plane reduced system
// (ReducedForcedSystem) and the textbook normal forms of the tests implement the small ForcedSystem
// interface. Two-parameter orbit problems and the PD curve: orbit_two_parameter.hpp.
//
// Angles modulo 2 pi: a tumbling orbit of the reduced system (Psi advances by -2 pi k per period) is
// still closed in the regular coordinates y = (Re z, Im z, w), because Psi only enters through
// z = r e^{-i Psi}. The unknowns therefore never carry an angle and need no unwrapping; the winding
// number is a property of the solution, computed afterwards (orbit_summary).
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/forced_system.hpp"
#include "rbcstab/continuation/problem.hpp"
#include "rbcstab/core/enum_table.hpp"

namespace rbcstab {

struct OrbitOptions {
  int segments = 8;              // shooting segments N: more = better conditioned Newton for unstable orbits
  double rtol = 1e-12;           // integration tolerance of each segment (with its variational equations)
  double atol = 1e-13;           // absolute tolerance (states are O(1))
  int samples_per_segment = 64;  // dense samples for r_min/max, Psi_min/max (the winding is integrated)
  // Every integration's IntegratorOptions::poll (the shootings; continue_scene: also the start's relaxation
  // for relax_T and to the orbit): a front end abandons a long run through it (it may throw). Not saved.
  std::function<void()> poll{};
  void validate() const;  // throws InvalidArgument naming the field
};

// Floquet data of a periodic orbit at t = 0: the monodromy M = M_{N-1} ... M_0 (plain product; the
// 3 x 3 case loses nothing measurable at rtol 1e-12, docs/continuation.md), the nontrivial
// multipliers (on the sphere's tangent plane x0^perp, which M leaves invariant when |x|^2 is conserved)
// and the trivial one x0^T M x0 / |x0|^2 (exactly 1 in exact arithmetic).
struct Floquet {
  Eigen::MatrixXd monodromy;
  Eigen::VectorXcd multipliers;   // nontrivial (all of them when no norm is conserved)
  std::optional<double> trivial;  // only for conserves_norm systems
};

enum class OrbitKind { swinging, tumbling };
template <>
struct EnumTable<OrbitKind> {
  static constexpr EnumName<OrbitKind> entries[] = {{OrbitKind::swinging, "swinging"},
                                                    {OrbitKind::tumbling, "tumbling"}};
};
// The name of the swinging <-> tumbling UZ event on orbit branches (transition_event's default).
inline constexpr std::string_view kTransitionEventName = "swing_tumble";

// What an orbit looks like over one period (reduced system: r, Psi of z = r e^{-i Psi}).
struct OrbitSummary {
  double r0 = 0, Psi0 = 0;          // at t = 0 (Psi0 in (-pi, pi])
  double r_min = 0, r_max = 0;      // the solution's (refined between samples to the integration tolerance)
  double t_r_min = 0;               // the time of r_min in [0, L) (L = 2 pi k, the orbit's period)
  double Psi_min = 0, Psi_max = 0;  // of the continuous Psi(t) started at Psi0 over [0, L], refined so
  int winding = 0;                  // turns of z around 0 per period (counter-clockwise); Psi advances -2 pi winding
  OrbitKind kind = OrbitKind::swinging;
  double transition_function = 0;  // +r_min when swinging, -r_min when tumbling: continuous, 0 at the transition
  Eigen::VectorXd mean;            // period average of x (periodic trapezoid rule on the uniform samples:
                                   // spectrally accurate for a smooth periodic orbit)
};

// Whole forcing periods of x' = f(t, x, p) from a state at t = 0 (mod 2 pi): how far a relaxation got.
struct OrbitRelaxation {
  Eigen::VectorXd x;                                         // the state after `periods` periods (t = 0 mod 2 pi)
  int periods = 0;                                           // forcing periods integrated
  double defect = std::numeric_limits<double>::quiet_NaN();  // |x(2 pi k) - x(2 pi (k - 1))|_2 of the last period
  bool converged = false;                                    // defect < tol before max_periods
  std::string failure;  // non-empty: the integration failed (x is the last state reached)
};

// The orbit's state at a time t and its first derivatives (PeriodicOrbitProblem::point_at).
struct OrbitPoint {
  bool ok = false;     // false: the integration failed (the other fields are then empty)
  int segment = 0;     // j: t (mod L) lies in [t_j, t_{j+1}), the state is phi(t, t_j, x_j)
  Eigen::VectorXd x;   // the state
  Eigen::MatrixXd dx;  // d x / d x_j (the segment's variational matrix up to t)
  Eigen::VectorXd dt;  // d x / d t = f(t, x, p)
  Eigen::VectorXd dp;  // d x / d p (the parameter sensitivity from t_j)
};

// The segment flows of a multiple shooting (detail/shooting.hpp): phi_j(x_j) at the segment's end, its
// variational matrix and parameter sensitivity; ok = false after a failed integration.
struct ShootingFlows {
  bool ok = false;
  std::vector<Eigen::VectorXd> phi, s;  // phi_j(x_j), d phi_j / dp
  std::vector<Eigen::MatrixXd> M;       // d phi_j / d x_j
};

// F(X, p) = 0 for X = (x_0, ..., x_{N-1}), x_j the state at t_j = L j / N (L = 2 pi k):
//   E_j = phi(t_{j+1}, t_j, x_j) - x_{j+1}  (x_N = x_0), and for conserves_norm systems
//   E_0 = |x_0|^2 phi(t_1, t_0, x_0) - x_1, which forces |x_0| = 1 at a zero and makes the Jacobian
//   regular where the trivial multiplier is simple (docs/continuation.md). The system must outlive
//   the problem.
class PeriodicOrbitProblem final : public ContinuationProblem {
 public:
  // periods k >= 1: orbits of period 2 pi k (the doubled orbit past a PD: k = 2); t_j = 2 pi k j / N.
  PeriodicOrbitProblem(const ForcedSystem& system, const OrbitOptions& options = {}, int periods = 1);
  Eigen::Index dimension() const override { return n_ * N_; }
  void residual(const Eigen::VectorXd& X, double p, Eigen::VectorXd& F) const override;
  void jacobian(const Eigen::VectorXd& X, double p, Eigen::MatrixXd& J) const override;
  void parameter_derivative(const Eigen::VectorXd& X, double p, Eigen::VectorXd& Fp) const override;
  StabilityKind stability_kind() const override { return StabilityKind::multipliers; }
  Eigen::VectorXcd spectrum(const Eigen::VectorXd& X, double p) const override;
  // The multipliers with first-order bounds (certified_eigenvalues of the monodromy on x0^perp) for a
  // monodromy off by |trivial multiplier - 1| relative (the integration error it shows along x0; at
  // least rtol); refine: each also at least its distance to the multipliers recomputed with twice the
  // segments at rtol / 100 (about twice a shooting's cost).
  CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& X, double p, bool refine) const override;
  std::string parameter_name() const override { return sys_.parameter_name(); }

  int segments() const { return N_; }
  int periods() const { return periods_; }
  const ForcedSystem& system() const { return sys_; }
  // The linearised solution through v0 at t = 0, at the segments' starts (v_0 = v0, v_{j+1} = M_j v_j), as the
  // unknowns' layout; the PD switch's direction (orbit_switch.hpp).
  Eigen::VectorXd variation(const Eigen::VectorXd& X, double p, const Eigen::VectorXd& v0) const;
  const OrbitOptions& options() const { return o_; }
  // The shooting unknowns of the trajectory through x0 at t = 0 (a start for Newton).
  Eigen::VectorXd shooting_guess(const Eigen::VectorXd& x0, double p) const;
  Eigen::VectorXd state_at_zero(const Eigen::VectorXd& X) const { return X.head(n_); }
  // Relaxes x' = f(t, x, p) from x0 (at t = 0 mod 2 pi) in chunks of `chunk` orbit periods L until the
  // periodicity defect of the last period is below tol or max_periods have run (the shooting's
  // integrator options). Near an attracting orbit with leading multiplier rho the defect shrinks by
  // |rho| per period and the distance to the orbit is ~ defect / (1 - |rho|).
  OrbitRelaxation relax(const Eigen::VectorXd& x0, double p, double tol, int max_periods, int chunk = 10) const;
  Floquet floquet(const Eigen::VectorXd& X, double p) const;
  // Integrates the orbit densely from the segments' states (winding via the integrated angle of z).
  // extrema = false: r_max and the Psi range stay the sampled ones (the transition event needs r_min only).
  OrbitSummary summary(const Eigen::VectorXd& X, double p, bool extrema = true) const;
  // The swinging <-> tumbling transition as a UZ event: summary().transition_function. Located along a
  // branch; its curve in two parameters uses the smooth form OrbitPassageEvent (event_curve.hpp).
  UserEvent transition_event(const std::string& name = std::string(kTransitionEventName)) const;
  // The state at time t (any real; taken mod L) integrated from its segment's start, with its
  // derivatives by that start, by t and by p: smooth in (X, t, p) within a segment, and continuous
  // across segment ends at a solution (where the segments join).
  OrbitPoint point_at(const Eigen::VectorXd& X, double p, double t) const;
  // Counters of the integrations done so far (work measure for benchmarks).
  std::size_t integrations() const { return integrations_; }
  // The shooting Jacobian of the anti-periodic problem x_N = -x_0 (closing block +I, no norm term):
  // singular exactly where det(M + I) = 0, i.e. a multiplier -1 (the bordered PD test function).
  void antiperiodic_jacobian(const Eigen::VectorXd& X, double p, Eigen::MatrixXd& J) const;
  // Forget the cached shooting (the system changed behind the problem's back, e.g. a second parameter).
  void clear_cache() const { cache_.valid = false; }

 private:
  struct Shooting : ShootingFlows {
    Eigen::VectorXd X;
    double p = 0;
    bool valid = false;
  };
  const Shooting& shoot(const Eigen::VectorXd& X, double p) const;
  const Shooting& cyclic_jacobian(const Eigen::VectorXd& X, double p, double closing_sign, Eigen::MatrixXd& J) const;
  const ForcedSystem& sys_;
  OrbitOptions o_;
  Eigen::Index n_;
  int N_;
  int periods_;
  double length_;  // 2 pi periods_
  mutable Shooting cache_;
  mutable std::size_t integrations_ = 0;
};

}  // namespace rbcstab
