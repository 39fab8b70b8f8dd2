// Orbit branches started at HB and PD points (orbit_switch.hpp) against closed forms: the Hopf normal form (super-
// and subcritical, with a quintic term for a fold of cycles, and in non-normal coordinates), a forced system whose
// doubled orbit is known, and the refusals of multiple points.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "continuation/autonomised_fixture.hpp"
#include "continuation/modal_fixtures.hpp"
#include "continuation/scene_spec_fixture.hpp"
#include "rbcstab/continuation/autonomous_orbit.hpp"
#include "rbcstab/continuation/branch_io.hpp"
#include "rbcstab/continuation/branch_tree.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/full_equilibrium.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/orbit_switch.hpp"
#include "rbcstab/continuation/period_map_normal_form.hpp"
#include "rbcstab/continuation/poincare_map.hpp"
#include "rbcstab/continuation/scene_continuation.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {

// u' = a(|u|^2) u + omega R u with a(rho) = p + s rho + c rho^2 (R the quarter turn), z' = -z (dim 3), seen in the
// coordinates y = A x. Orbits: |u|^2 = rho with a(rho) = 0, period 2 pi / omega, z = 0; the radial multiplier is
// e^{2 rho a'(rho) T}, the z one e^{-T}.
class HopfNormalForm final : public AutonomousSystem {
 public:
  HopfNormalForm(double s, double c, double omega, Eigen::MatrixXd A)
      : s_(s), c_(c), w_(omega), A_(std::move(A)), Ainv_(A_.inverse()) {}
  Eigen::Index dimension() const override { return A_.rows(); }
  Eigen::VectorXd x_of(const Eigen::VectorXd& y) const { return Ainv_ * y; }
  void rhs(std::span<const double> y, double p, std::span<double> f) const override {
    const Eigen::VectorXd x = x_of(Eigen::Map<const Eigen::VectorXd>(y.data(), dimension()));
    Eigen::Map<Eigen::VectorXd>(f.data(), dimension()) = A_ * fx(x, p).head(dimension());
  }
  void jacobian(std::span<const double> y, double p, Eigen::MatrixXd& J) const override {
    const Eigen::VectorXd x = x_of(Eigen::Map<const Eigen::VectorXd>(y.data(), dimension()));
    const double rho = x.head(2).squaredNorm(), a = p + s_ * rho + c_ * rho * rho, da = s_ + 2 * c_ * rho;
    Eigen::MatrixXd Jx = Eigen::MatrixXd::Zero(dimension(), dimension());
    Jx.topLeftCorner(2, 2) << a, -w_, w_, a;
    Jx.topLeftCorner(2, 2) += 2 * da * x.head(2) * x.head(2).transpose();
    if (dimension() == 3) Jx(2, 2) = -1;
    J = A_ * Jx * Ainv_;
  }
  void parameter_derivative(std::span<const double> y, double, std::span<double> fp) const override {
    Eigen::VectorXd x = x_of(Eigen::Map<const Eigen::VectorXd>(y.data(), dimension()));
    if (dimension() == 3) x[2] = 0;
    Eigen::Map<Eigen::VectorXd>(fp.data(), dimension()) = A_ * x;
  }
  double a_prime(double rho) const { return s_ + 2 * c_ * rho; }

 private:
  // In fixed size (z = 0 in dimension 2): the dynamic-size version trips GCC's -Wnull-dereference.
  Eigen::Vector3d fx(const Eigen::VectorXd& xd, double p) const {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    x.head(xd.size()) = xd;
    const double rho = x.head<2>().squaredNorm(), a = p + s_ * rho + c_ * rho * rho;
    return {a * x[0] - w_ * x[1], w_ * x[0] + a * x[1], -x[2]};
  }
  double s_, c_, w_;
  Eigen::MatrixXd A_, Ainv_;
};

// The equilibrium branch x = 0 over p in [-0.3, 0.3] and its HB at p = 0.
Branch equilibrium_branch(const AutonomousEquilibriumProblem& eq) {
  ContinuationOptions o;
  o.p_min = -0.3;
  o.p_max = 0.3;
  o.max_step = 0.1;
  return continue_branch(eq, Eigen::VectorXd::Zero(eq.dimension()), -0.3, o);
}

OrbitSwitchOptions switch_options(double p_lo, double p_hi) {
  OrbitSwitchOptions so;
  so.orbit.segments = 4;
  so.continuation.p_min = p_lo;
  so.continuation.p_max = p_hi;
  so.continuation.max_step = 0.1;
  so.continuation.max_points = 40;
  return so;
}

// Every point of an orbit branch of sys against the closed form: a(|u_0|^2) = 0 (with z_0 = 0), T = 2 pi / omega,
// the multipliers e^{2 rho a' T} (and e^{-T}). Tolerances: the shooting integrates at rtol 1e-12 and Newton stops
// at 1e-12, so the orbit is exact to ~1e-11 per period; 1e-8 leaves room for the O(1) amplification in A.
void expect_closed_form(const HopfNormalForm& sys, const Branch& b, double s, double c, double omega) {
  ASSERT_GE(b.points.size(), 5u) << b.message;
  const double T = kTwoPi / omega;
  for (const BranchPoint& pt : b.points) {
    const Eigen::VectorXd x0 = sys.x_of(pt.x.head(sys.dimension()));
    const double rho = x0.head(2).squaredNorm();
    EXPECT_NEAR(pt.p + s * rho + c * rho * rho, 0, 1e-8) << pt.p;
    if (sys.dimension() == 3) {
      EXPECT_NEAR(x0[2], 0, 1e-8);
    }
    EXPECT_NEAR(AutonomousOrbitProblem::period(pt.x), T, 1e-8);
    ASSERT_EQ(pt.spectrum.size(), sys.dimension() - 1);
    std::vector<double> mu, ex = {std::exp(2 * rho * sys.a_prime(rho) * T)};
    for (const auto& m : pt.spectrum) mu.push_back(m.real());
    if (sys.dimension() == 3) ex.push_back(std::exp(-T));
    std::sort(mu.begin(), mu.end());
    std::sort(ex.begin(), ex.end());
    for (std::size_t i = 0; i < mu.size(); ++i) EXPECT_NEAR(mu[i], ex[i], 1e-8 * std::max(1.0, ex[i])) << pt.p;
  }
}

TEST(HopfSwitch, SupercriticalNormalForm) {
  const HopfNormalForm sys(-1, 0, 1.3, Eigen::MatrixXd::Identity(2, 2));
  const AutonomousEquilibriumProblem eq(sys);
  const Branch e = equilibrium_branch(eq);
  const SpecialPoint* hb = find_special_point(e, SpecialPointType::HB);
  ASSERT_NE(hb, nullptr);
  EXPECT_NEAR(hb->p, 0, 1e-10);
  const OrbitSwitchResult r = switch_at(eq, e, *hb, switch_options(-1, 0.5));
  ASSERT_TRUE(r.switched) << r.message;
  EXPECT_NEAR(r.period, kTwoPi / 1.3, 1e-12);
  EXPECT_EQ(r.branch.status, ContinuationStatus::completed) << r.branch.message;
  EXPECT_NEAR(r.branch.points.back().p, 0.5, 1e-12);  // away from the HB: p increases (r^2 = p)
  expect_closed_form(sys, r.branch, -1, 0, 1.3);
  for (const BranchPoint& pt : r.branch.points) EXPECT_TRUE(pt.stable);
  // The period is a column of the branch's JSON, after the parameter.
  MeasuredBranch m;
  m.branch = r.branch;
  m.spectrum_kind = StabilityKind::multipliers;
  m.point_measures.assign(r.branch.points.size(), {});
  m.special_measures.assign(r.branch.special_points.size(), {});
  const nlohmann::json j = to_json(m);
  ASSERT_EQ(r.branch.parameter_names, (std::vector<std::string>{"p", "T"}));
  EXPECT_NEAR(j["branch"][1]["T"].get<double>(), kTwoPi / 1.3, 1e-8);
  EXPECT_EQ(j["branch"][1]["p"].get<double>(), r.branch.points[1].p);
}

TEST(HopfSwitch, SubcriticalNormalFormInSkewedCoordinates) {
  Eigen::MatrixXd A(3, 3);
  A << 1, 0.5, 0.2, 0.3, 1, -0.4, 0.1, 0.2, 2;
  const HopfNormalForm sys(1, 0, 0.7, A);
  const AutonomousEquilibriumProblem eq(sys);
  const Branch e = equilibrium_branch(eq);
  const SpecialPoint* hb = find_special_point(e, SpecialPointType::HB);
  ASSERT_NE(hb, nullptr);
  const OrbitSwitchResult r = switch_at(eq, e, *hb, switch_options(-0.5, 1));
  ASSERT_TRUE(r.switched) << r.message;
  EXPECT_NEAR(r.branch.points.back().p, -0.5, 1e-12);  // the unstable orbits lie below the HB (r^2 = -p)
  expect_closed_form(sys, r.branch, 1, 0, 0.7);
  for (const BranchPoint& pt : r.branch.points) EXPECT_EQ(pt.n_unstable, 1);
}

// a(rho) = p + rho - rho^2: the subcritical orbits turn at the fold of cycles p = -1/4, rho = 1/2 (LPC) and come
// back stable (rho = (1 + sqrt(1 + 4 p)) / 2).
TEST(HopfSwitch, FoldOfCyclesOnTheSwitchedBranch) {
  const HopfNormalForm sys(1, -1, 1.0, Eigen::MatrixXd::Identity(2, 2));
  const AutonomousEquilibriumProblem eq(sys);
  const Branch e = equilibrium_branch(eq);
  const SpecialPoint* hb = find_special_point(e, SpecialPointType::HB);
  ASSERT_NE(hb, nullptr);
  OrbitSwitchOptions so = switch_options(-1, 0.2);
  const OrbitSwitchResult r = switch_at(eq, e, *hb, so);
  ASSERT_TRUE(r.switched) << r.message;
  const SpecialPoint* lpc = find_special_point(r.branch, SpecialPointType::LPC);
  ASSERT_NE(lpc, nullptr) << r.branch.message;
  EXPECT_EQ(lpc->status, LocationStatus::located);
  EXPECT_NEAR(lpc->p, -0.25, 1e-7);  // the fold of a(rho) = 0 (location tolerance 1e-11 in (X, p), curvature O(1))
  EXPECT_NEAR(sys.x_of(lpc->x.head(2)).squaredNorm(), 0.5, 1e-5);  // rho - 1/2 ~ sqrt(p error)
  // The LPC carries the Poincare map's fold: on the section (the radial line through x0*) the orbits lie at
  // |r - r*| = sqrt(p - p*) / (2 r*) to leading order (rho = 1/2 +- sqrt(p - p*)), amplitude 1 / sqrt 2, side +1.
  ASSERT_TRUE(lpc->normal_form.has_value());
  const NormalForm& nf = *lpc->normal_form;
  EXPECT_EQ(nf.kind, NormalFormKind::fold_of_cycles);
  EXPECT_EQ(nf.criticality, Criticality::not_applicable) << nf.note;
  EXPECT_NEAR(nf.amplitude, std::sqrt(0.5), 1e-5) << nf.note;  // measured 3e-8 (second differences: ~1e-6)
  EXPECT_EQ(nf.side, 1);
  expect_closed_form(sys, r.branch, 1, -1, 1.0);
  EXPECT_TRUE(r.branch.points.back().stable);
}

// The fold of cycles of a(rho) = p + rho - rho^2 (LPC at p* = -1/4, rho* = 1/2) in the skewed coordinates y = A x, at
// the exact fold orbit through x* = r* (cos phi0, sin phi0, 0): the closed-form orbits near it, r^2 = 1/2 +-
// sqrt(p - p*), meet the section S through y* (normal f(y*)) where <n, A (r e(phi), 0) - y*> = 0.
const Eigen::Matrix3d kSkew = (Eigen::Matrix3d() << 1, 0.5, 0.2, 0.3, 1, -0.4, 0.1, 0.2, 2).finished();
constexpr double kFoldPhase = 0.4, kFoldP = -0.25;
Eigen::Vector3d fold_orbit_point(double r, double phi) {
  return kSkew * Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), 0);
}
// The fold's amplitude law in closed form at the fold orbit's point y* = A x* (the section through y* normal to
// f(y*)): a radial step dr meets S after the angle d phi with <m, dr e_r + r* d phi e_phi> = 0 (m = A^T n), so
// |y - y*| = |A v| |dr|, v = e_r - (<m, e_r> / <m, e_phi>) e_phi, and dr = +-sqrt(p - p*) / (2 r*).
double fold_law(const HopfNormalForm& sys, const Eigen::Vector3d& ys) {
  Eigen::Vector3d f;
  sys.rhs(std::span<const double>(ys.data(), 3), kFoldP, std::span<double>(f.data(), 3));
  const Eigen::Vector3d xs = sys.x_of(ys), m = kSkew.transpose() * f.normalized();
  const double rs = xs.head<2>().norm();
  const Eigen::Vector3d er(xs[0] / rs, xs[1] / rs, 0), ephi(-er[1], er[0], 0);
  const Eigen::Vector3d v = er - (m.dot(er) / m.dot(ephi)) * ephi;
  return (kSkew * v).norm() / (2 * rs);
}
OrbitOptions four_segment_orbit() {
  OrbitOptions oo;
  oo.segments = 4;
  return oo;
}

TEST(PoincareMap, DerivativeIsTheProjectedMonodromy) {
  const HopfNormalForm sys(1, -1, 1.0, kSkew);
  const AutonomousOrbitProblem pr(sys, 0, four_segment_orbit());
  const Eigen::VectorXd X = pr.shooting_guess(fold_orbit_point(std::sqrt(0.5), kFoldPhase), kTwoPi, kFoldP);
  const PoincareMap map(pr, X, kFoldP);
  ASSERT_EQ(map.dimension(), 2);
  EXPECT_NEAR((map.basis().transpose() * map.basis() - Eigen::Matrix2d::Identity()).norm(), 0, 1e-14);
  EXPECT_NEAR((map.basis().transpose() * map.normal()).norm(), 0, 1e-14);
  Eigen::VectorXd F;
  map.residual(Eigen::Vector2d::Zero(), kFoldP, F);
  EXPECT_LT(F.norm(), 1e-10);  // the orbit's point is fixed (rtol 1e-12 over a period)
  EXPECT_NEAR(map.return_time(Eigen::Vector2d::Zero(), kFoldP), kTwoPi, 1e-10);
  // DP and P_p against central differences of P (h = 1e-5: truncation ~1e-10, rounding ~1e-12 / h = 1e-7; measured
  // 4.5e-9 and 8.1e-9 for DP, 7e-8 and 1.7e-7 for P_p): at the orbit and off it, where f at the return is not along n
  // and the projection I - f n^T / <n, f> matters (the unprojected Q^T M Q is off by 0.089 there).
  const double h = 1e-5;
  for (const Eigen::Vector2d& xi : {Eigen::Vector2d(0, 0), Eigen::Vector2d(0.05, -0.03)}) {
    Eigen::Matrix2d fd;
    for (int k = 0; k < 2; ++k) {
      Eigen::VectorXd Fa, Fb;
      map.residual(xi + h * Eigen::Vector2d::Unit(k), kFoldP, Fa);
      map.residual(xi - h * Eigen::Vector2d::Unit(k), kFoldP, Fb);
      fd.col(k) = (Fa - Fb) / (2 * h) + Eigen::Vector2d::Unit(k);
    }
    const Eigen::MatrixXd A = map.map_jacobian(xi, kFoldP);
    EXPECT_LT((A - fd).norm(), 1e-6) << A << "\n" << fd;
    Eigen::VectorXd Fp, Fa, Fb;
    map.parameter_derivative(xi, kFoldP, Fp);
    map.residual(xi, kFoldP + h, Fa);
    map.residual(xi, kFoldP - h, Fb);
    EXPECT_LT((Fp - (Fa - Fb) / (2 * h)).norm(), 1e-6) << Fp.transpose();
    if (xi.norm() > 0) {
      // The unprojected Q^T M Q is off by O(|xi|): the check can fail.
      Eigen::VectorXd y;
      const double tau = map.return_time(xi, kFoldP, &y);
      const Eigen::MatrixXd M = pr.monodromy(pr.shooting_guess(map.point(xi), tau, kFoldP), kFoldP);
      EXPECT_GT((map.basis().transpose() * M * map.basis() - fd).norm(), 1e-3);
    } else {
      // The closed-form multipliers at the fold: the radial e^{2 rho a'(rho) T} = 1 and the slaved e^{-T}.
      const Eigen::VectorXcd ev = Eigen::EigenSolver<Eigen::MatrixXd>(A).eigenvalues();
      std::vector<double> mu = {ev[0].real(), ev[1].real()};
      std::sort(mu.begin(), mu.end());
      EXPECT_NEAR(mu[0], std::exp(-kTwoPi), 1e-9);
      EXPECT_NEAR(mu[1], 1, 1e-9);
    }
  }
}

// Bad input: unknowns of another size, a point where f = 0 (no section), a period <= 0: InvalidArgument naming it;
// through the engine's entry, a not_computed normal form saying why.
TEST(PoincareMap, RefusesAPointWithoutASection) {
  const HopfNormalForm sys(1, -1, 1.0, kSkew);
  const AutonomousOrbitProblem pr(sys, 0, four_segment_orbit());
  const Eigen::VectorXd X = pr.shooting_guess(fold_orbit_point(std::sqrt(0.5), kFoldPhase), kTwoPi, kFoldP);
  const auto refusal = [&](const Eigen::VectorXd& Y) {
    try {
      const PoincareMap map(pr, Y, kFoldP);
      return std::string("no throw");
    } catch (const InvalidArgument& e) {
      return e.parameter();
    }
  };
  EXPECT_EQ(refusal(X.head(5)), "X");
  Eigen::VectorXd at_rest = pr.shooting_guess(Eigen::Vector3d::Zero(), kTwoPi, kFoldP), no_period = X;
  EXPECT_EQ(refusal(at_rest), "|f(x0)|");
  no_period[no_period.size() - 1] = -1;
  EXPECT_EQ(refusal(no_period), "T");
  SpecialPoint sp;
  sp.type = SpecialPointType::PD;
  sp.status = LocationStatus::located;
  sp.x = at_rest;
  sp.p = kFoldP;
  const NormalForm nf = period_map_normal_form(pr, sp);
  EXPECT_EQ(nf.criticality, Criticality::not_computed);
  EXPECT_NE(nf.note.find("|f(x0)|"), std::string::npos) << nf.note;
}

TEST(AutonomousOrbitNormalForm, FoldOfCyclesAgainstTheClosedForm) {
  const HopfNormalForm sys(1, -1, 1.0, kSkew);
  const AutonomousOrbitProblem pr(sys, 0, four_segment_orbit());
  const double rs = std::sqrt(0.5);
  const Eigen::Vector3d ys = fold_orbit_point(rs, kFoldPhase);
  const NormalForm nf = fold_of_cycles_normal_form(pr, pr.shooting_guess(ys, kTwoPi, kFoldP), kFoldP);
  EXPECT_EQ(nf.kind, NormalFormKind::fold_of_cycles);
  EXPECT_EQ(nf.criticality, Criticality::not_applicable) << nf.note;
  EXPECT_EQ(nf.exponent, 0.5);
  EXPECT_EQ(nf.side, 1);  // the orbits exist for p > p*
  EXPECT_GT(nf.coefficient("p2"), 0);
  const double law = fold_law(sys, ys);
  Eigen::Vector3d f;
  sys.rhs(std::span<const double>(ys.data(), 3), kFoldP, std::span<double>(f.data(), 3));
  const Eigen::Vector3d er(std::cos(kFoldPhase), std::sin(kFoldPhase), 0);
  // Measured 1e-9 relative; bar 1e-5 (second differences of shootings: ~1e-6).
  EXPECT_NEAR(nf.amplitude, law, 1e-5 * law) << nf.note;
  // The radial distance alone (no slant of the section) is off by far more: the check can fail.
  EXPECT_GT(std::abs((kSkew * er).norm() / (2 * rs) - law), 0.05 * law);
  // The exact orbits' intersections with S against the law at two distances: the error is O(sqrt(p - p*)).
  std::vector<double> errors;
  for (const double dp : {1e-4, 1e-6}) {
    double worst = 0;
    for (const double branch : {-1.0, 1.0}) {
      const double r = std::sqrt(0.5 + branch * std::sqrt(dp));
      double phi = kFoldPhase;
      for (int it = 0; it < 50; ++it) {
        const Eigen::Vector3d e(-std::sin(phi), std::cos(phi), 0);
        phi -= f.dot(fold_orbit_point(r, phi) - ys) / (r * f.dot(kSkew * e));
      }
      const double dist = (fold_orbit_point(r, phi) - ys).norm();
      worst = std::max(worst, std::abs(dist / (nf.amplitude * std::sqrt(dp)) - 1));
    }
    errors.push_back(worst);
  }
  // Measured 9.7e-3 and 9.5e-4 (the sqrt(p - p*) shrinkage: 10.2 for a factor 100).
  EXPECT_LT(errors[0], 3e-2) << errors[0];
  EXPECT_LT(errors[1], 3e-3) << errors[1];
  EXPECT_LT(errors[1], errors[0] / 5) << errors[0] << " " << errors[1];
}

// The Brusselator x' = a - (b + 1) x + x^2 y, y' = b x - x^2 y (a = 1, free b): the equilibrium (a, b / a) has its
// Hopf point at b = 1 + a^2 with omega = a; no closed form for the orbit, so the switched branch is checked against
// a long simulation by an independent integrator (classical RK4).
class Brusselator final : public AutonomousSystem {
 public:
  Eigen::Index dimension() const override { return 2; }
  void rhs(std::span<const double> x, double b, std::span<double> f) const override {
    f[0] = 1 - (b + 1) * x[0] + x[0] * x[0] * x[1];
    f[1] = b * x[0] - x[0] * x[0] * x[1];
  }
  void jacobian(std::span<const double> x, double b, Eigen::MatrixXd& J) const override {
    J.resize(2, 2);
    J << -(b + 1) + 2 * x[0] * x[1], x[0] * x[0], b - 2 * x[0] * x[1], -x[0] * x[0];
  }
  void parameter_derivative(std::span<const double> x, double, std::span<double> fp) const override {
    fp[0] = -x[0];
    fp[1] = x[0];
  }
};

// The attractor at b by RK4 (dt = 1e-3) from next to the equilibrium, relaxed for t = 400: the period between the
// last two maxima of component k and the maximum and minimum of that component (parabolic interpolation).
struct Simulated {
  double period = 0, max = -1e300, min = 1e300;
};
Simulated simulate_brusselator(double b, int k) {
  const Brusselator sys;
  const double dt = 1e-3;
  std::array<double, 2> x = {1.1, b - 0.1};
  auto f = [&](const std::array<double, 2>& y) {
    std::array<double, 2> d{};
    sys.rhs(y, b, d);
    return d;
  };
  std::vector<double> peaks;
  double prev2 = 0, prev1 = 0;
  Simulated s;
  for (int i = 0; i < 460000; ++i) {
    const auto k1 = f(x);
    const auto k2 = f({x[0] + dt / 2 * k1[0], x[1] + dt / 2 * k1[1]});
    const auto k3 = f({x[0] + dt / 2 * k2[0], x[1] + dt / 2 * k2[1]});
    const auto k4 = f({x[0] + dt * k3[0], x[1] + dt * k3[1]});
    for (int c = 0; c < 2; ++c) x[c] += dt / 6 * (k1[c] + 2 * k2[c] + 2 * k3[c] + k4[c]);
    const double v = x[static_cast<std::size_t>(k)];
    // prev1 (the state after step i - 1) is an extremum of the samples: the parabola through (prev2, prev1, v)
    // gives its time and value.
    if (i >= 400000 && ((prev1 > prev2 && prev1 >= v) || (prev1 < prev2 && prev1 <= v))) {
      const double den = prev2 - 2 * prev1 + v;
      const double shift = 0.5 * (prev2 - v) / den, value = prev1 - 0.25 * (prev2 - v) * shift;
      if (prev1 > prev2) {
        s.max = std::max(s.max, value);
        peaks.push_back((i + shift) * dt);
      } else {
        s.min = std::min(s.min, value);
      }
    }
    prev2 = prev1;
    prev1 = v;
  }
  s.period = peaks.size() >= 2 ? peaks.back() - peaks[peaks.size() - 2] : 0;
  return s;
}

TEST(HopfSwitch, BrusselatorAgainstSimulation) {
  const Brusselator sys;
  const AutonomousEquilibriumProblem eq(sys);
  ContinuationOptions o;
  o.p_min = 1.5;
  o.p_max = 2.5;
  o.max_step = 0.1;
  const Branch e = continue_branch(eq, Eigen::Vector2d(1, 1.5), 1.5, o);
  const SpecialPoint* hb = find_special_point(e, SpecialPointType::HB);
  ASSERT_NE(hb, nullptr);
  EXPECT_NEAR(hb->p, 2, 1e-9);                  // b = 1 + a^2
  EXPECT_NEAR(hb->eigenvalue.imag(), 1, 1e-9);  // omega = a
  const OrbitSwitchResult r = switch_at(eq, e, *hb, switch_options(1.5, 2.3));
  ASSERT_TRUE(r.switched) << r.message;
  const BranchPoint& last = r.branch.points.back();
  ASSERT_NEAR(last.p, 2.3, 1e-12);
  EXPECT_TRUE(last.stable);
  const auto* orbit = dynamic_cast<const AutonomousOrbitProblem*>(r.problem.get());
  ASSERT_NE(orbit, nullptr);
  const int k = orbit->phase_component();
  const Simulated s = simulate_brusselator(2.3, k);
  // RK4 at dt = 1e-3 is accurate to ~1e-11 per unit time here, the parabolic interpolation of an extremum to
  // ~dt^3 times the third derivative (~1e-8): 1e-6 leaves room for both. x_0 is an extremum of component k.
  EXPECT_NEAR(AutonomousOrbitProblem::period(last.x), s.period, 1e-6);
  const double xk = last.x[k];
  EXPECT_NEAR(std::min(std::abs(xk - s.max), std::abs(xk - s.min)), 0, 1e-6) << xk << " " << s.max << " " << s.min;
  EXPECT_GT(s.max - s.min, 0.1);  // a grown orbit, not the equilibrium
}

// Two pairs crossing at once (omega 1 and 2): refused, naming both pairs.
class DoubleHopf final : public AutonomousSystem {
 public:
  Eigen::Index dimension() const override { return 4; }
  void rhs(std::span<const double> x, double p, std::span<double> f) const override {
    for (int b = 0; b < 2; ++b) {
      const double w = b + 1.0, r = x[2 * b] * x[2 * b] + x[2 * b + 1] * x[2 * b + 1];
      f[2 * b] = (p - r) * x[2 * b] - w * x[2 * b + 1];
      f[2 * b + 1] = w * x[2 * b] + (p - r) * x[2 * b + 1];
    }
  }
  void jacobian(std::span<const double> x, double p, Eigen::MatrixXd& J) const override {
    J.setZero(4, 4);
    for (int b = 0; b < 2; ++b) {
      const double w = b + 1.0;
      const Eigen::Vector2d u(x[2 * b], x[2 * b + 1]);
      Eigen::Matrix2d B;
      B << p - u.squaredNorm(), -w, w, p - u.squaredNorm();
      J.block(2 * b, 2 * b, 2, 2) = B - 2 * u * u.transpose();
    }
  }
};

TEST(HopfSwitch, MultipleHopfIsRefused) {
  const DoubleHopf sys;
  SpecialPoint hb;
  hb.type = SpecialPointType::HB;
  hb.x = Eigen::VectorXd::Zero(4);
  hb.p = 0;
  hb.eigenvalue = {0, 1};
  const OrbitSwitchResult r = switch_at_hopf(sys, hb);
  EXPECT_FALSE(r.switched);
  EXPECT_EQ(r.problem, nullptr);
  EXPECT_NE(r.message.find("not a simple Hopf point"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("1i"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("2i"), std::string::npos) << r.message;
  // Off the point (p = 0.1) no eigenvalue is critical: refused too (not an HB at all).
  hb.p = 0.1;
  EXPECT_NE(switch_at_hopf(sys, hb).message.find("none"), std::string::npos);
  // A PD label is not an HB, and a PD on an equilibrium branch has no orbit to double.
  hb.type = SpecialPointType::PD;
  EXPECT_THROW(switch_at_hopf(sys, hb), InvalidArgument);
  const AutonomousEquilibriumProblem eq(sys);
  EXPECT_FALSE(switch_at(eq, Branch{}, hb).switched);
}

// x = x_p(t) + R(t/2) u with u' = (a u1 - u1^3, -u2), a = p, x_p = (cos t, sin t + 0.3 sin 2t): f is 2 pi-periodic
// because g is odd and R(t/2 + pi) = -R(t/2). Orbits: x_p (multipliers -e^{2 pi p}, -e^{-2 pi}; PD at p = 0) and
// for p > 0 the doubled orbits x_p(t) +- sqrt(p) R(t/2) e_1 (period 4 pi, multipliers e^{-8 pi p}, e^{-4 pi}).
class ForcedPitchFlip final : public ForcedSystem {
 public:
  // cubic: the sign s of u1' = p u1 + s u1^3 (-1 above; +1 puts the doubled orbits at p < 0, unstable); quintic: a
  // term k u1^5 added (the doubled orbit's amplitude then follows sqrt(p) only to leading order).
  explicit ForcedPitchFlip(double cubic = -1, double quintic = 0) : s_(cubic), k_(quintic) {}
  static Eigen::Vector2d xp(double t) { return {std::cos(t), std::sin(t) + 0.3 * std::sin(2 * t)}; }
  static Eigen::Vector2d xp_dot(double t) { return {-std::sin(t), std::cos(t) + 0.6 * std::cos(2 * t)}; }
  static Eigen::Matrix2d R(double t) {
    Eigen::Matrix2d m;
    m << std::cos(t / 2), -std::sin(t / 2), std::sin(t / 2), std::cos(t / 2);
    return m;
  }
  Eigen::Index dimension() const override { return 2; }
  void rhs(double t, std::span<const double> x, double p, std::span<double> f) const override {
    const Eigen::Vector2d u = R(t).transpose() * (Eigen::Vector2d(x[0], x[1]) - xp(t));
    Eigen::Matrix2d half;
    half << 0, -0.5, 0.5, 0;
    const Eigen::Vector2d F =
        xp_dot(t) +
        R(t) * (half * u + Eigen::Vector2d(p * u[0] + s_ * std::pow(u[0], 3) + k_ * std::pow(u[0], 5), -u[1]));
    f[0] = F[0];
    f[1] = F[1];
  }
  void jacobian(double t, std::span<const double> x, double p, Eigen::MatrixXd& J) const override {
    const Eigen::Vector2d u = R(t).transpose() * (Eigen::Vector2d(x[0], x[1]) - xp(t));
    Eigen::Matrix2d D;
    D << p + 3 * s_ * u[0] * u[0] + 5 * k_ * std::pow(u[0], 4), -0.5, 0.5, -1;
    J = R(t) * D * R(t).transpose();
  }
  void parameter_derivative(double t, std::span<const double> x, double, std::span<double> fp) const override {
    const Eigen::Vector2d u = R(t).transpose() * (Eigen::Vector2d(x[0], x[1]) - xp(t));
    const Eigen::Vector2d F = R(t) * Eigen::Vector2d(u[0], 0);
    fp[0] = F[0];
    fp[1] = F[1];
  }

 private:
  double s_, k_;
};

TEST(PeriodDoublingSwitch, DoubledOrbitInClosedForm) {
  const ForcedPitchFlip sys;
  OrbitOptions oo;
  oo.segments = 4;
  const PeriodicOrbitProblem pr(sys, oo);
  const double p0 = -0.2;
  ContinuationOptions o;
  o.p_min = p0;
  o.p_max = 0.2;
  o.max_step = 0.1;
  const Branch b = continue_branch(pr, pr.shooting_guess(ForcedPitchFlip::xp(0), p0), p0, o);
  const SpecialPoint* pd = find_special_point(b, SpecialPointType::PD);
  ASSERT_NE(pd, nullptr) << b.message;
  EXPECT_NEAR(pd->p, 0, 1e-8);
  OrbitSwitchOptions so;
  so.orbit = oo;
  so.continuation = o;
  so.continuation.max_points = 30;
  const OrbitSwitchResult r = switch_at(pr, b, *pd, so);
  ASSERT_TRUE(r.switched) << r.message;
  EXPECT_NEAR(r.period, 4 * kPi, 1e-12);
  const auto* doubled = dynamic_cast<const PeriodicOrbitProblem*>(r.problem.get());
  ASSERT_NE(doubled, nullptr);
  EXPECT_EQ(doubled->periods(), 2);
  EXPECT_EQ(doubled->segments(), 8);
  ASSERT_GE(r.branch.points.size(), 5u);
  EXPECT_NEAR(r.branch.points.back().p, 0.2, 1e-12);
  for (const BranchPoint& pt : r.branch.points) {
    // The doubled orbit at every segment start t_j = pi j / 2 (1e-9: rtol 1e-12 over two periods), so its
    // amplitude grows exactly like sqrt(p).
    const double amp = std::sqrt(pt.p);
    const double sign = pt.x[0] > ForcedPitchFlip::xp(0)[0] ? 1 : -1;
    for (int j = 0; j < 8; ++j) {
      const double t = kPi * j / 2;
      const Eigen::Vector2d expected = ForcedPitchFlip::xp(t) + sign * amp * ForcedPitchFlip::R(t).col(0);
      EXPECT_NEAR((pt.x.segment(2 * j, 2) - expected).norm(), 0, 1e-9) << pt.p << " " << j;
    }
    std::vector<double> mu = {pt.spectrum[0].real(), pt.spectrum[1].real()};
    std::sort(mu.begin(), mu.end());
    std::vector<double> ex = {std::exp(-8 * kPi * pt.p), std::exp(-4 * kPi)};
    std::sort(ex.begin(), ex.end());
    EXPECT_NEAR(mu[0], ex[0], 1e-9);
    EXPECT_NEAR(mu[1], ex[1], 1e-9);
    EXPECT_TRUE(pt.stable);
  }
  // The same orbit started as a period-2 orbit at the doubled problem's bare Newton: periods = 2 is a problem on
  // its own (not only the switch's).
  const double p = 0.1;
  const Eigen::VectorXd X = doubled->shooting_guess(ForcedPitchFlip::xp(0) + Eigen::Vector2d(std::sqrt(p), 0), p);
  Eigen::VectorXd F;
  doubled->residual(X, p, F);
  EXPECT_LT(F.norm(), 1e-9);
  pr.residual(pr.shooting_guess(ForcedPitchFlip::xp(0) + Eigen::Vector2d(std::sqrt(p), 0), p), p, F);
  EXPECT_GT(F.norm(), 0.1);  // not 2 pi-periodic: the single-period problem rejects it
  // A point of the branch that is not a PD (p = -0.2: multipliers -e^{-0.4 pi}, -e^{-2 pi}) is refused, and so is a
  // type the orbit switch does not handle.
  SpecialPoint not_pd = *pd;
  not_pd.x = b.points.front().x;
  not_pd.p = b.points.front().p;
  const OrbitSwitchResult refused = switch_at(pr, b, not_pd, so);
  EXPECT_FALSE(refused.switched);
  EXPECT_NE(refused.message.find("not a simple period doubling"), std::string::npos) << refused.message;
  not_pd.type = SpecialPointType::LPC;
  EXPECT_NE(switch_at(pr, b, not_pd, so).message.find("no orbit switch at a LPC"), std::string::npos);
}

// The forced pitch-flip's orbit branch over p in [-0.2, 0.2] from its closed-form orbit at p = -0.2 (one PD, at 0).
ContinuationOptions pitch_flip_options() {
  ContinuationOptions o;
  o.p_min = -0.2;
  o.p_max = 0.2;
  o.max_step = 0.1;
  return o;
}
Branch pitch_flip_branch(const PeriodicOrbitProblem& pr, const ContinuationOptions& o) {
  return continue_branch(pr, pr.shooting_guess(ForcedPitchFlip::xp(0), -0.2), -0.2, o);
}
// The normal form at the PD of a pitch-flip system's orbit branch (4 shooting segments); nullopt, with the branch's
// message in `why`, when the branch has no PD with a normal form.
std::optional<NormalForm> pitch_flip_pd_form(const ForcedSystem& sys, std::string& why) {
  OrbitOptions oo;
  oo.segments = 4;
  const PeriodicOrbitProblem pr(sys, oo);
  const Branch b = pitch_flip_branch(pr, pitch_flip_options());
  const SpecialPoint* pd = find_special_point(b, SpecialPointType::PD);
  if (pd == nullptr || !pd->normal_form.has_value()) {
    why = b.message;
    return std::nullopt;
  }
  return *pd->normal_form;
}

// The PD's flip coefficient against the closed form: the period map over 2 pi in x - x_p (= u at t = 0, R(pi) = -I)
// is u1 -> -u1(2 pi) with u1' = s u1^3 at p = 0, u1(2 pi) = u1 + 2 pi s u1^3 + O(u1^5): c = -2 pi s. s = -1:
// supercritical (the doubled orbit exists for p > 0, where x_p is unstable, and is stable); s = +1: subcritical.
TEST(PeriodDoublingNormalForm, FlipCoefficientOfTheForcedSystem) {
  for (const double s : {-1.0, 1.0}) {
    std::string why;
    const std::optional<NormalForm> form = pitch_flip_pd_form(ForcedPitchFlip(s), why);
    ASSERT_TRUE(form.has_value()) << why;
    const NormalForm& nf = *form;
    EXPECT_EQ(nf.kind, NormalFormKind::period_doubling);
    // Measured 6.2831765 and -6.2831765 (1.4e-6 relative: the extrapolated differences' O(h^4)); bar 1e-4.
    EXPECT_NEAR(nf.coefficient("c"), -2 * kPi * s, 1e-4) << nf.note;
    EXPECT_EQ(nf.criticality, s < 0 ? Criticality::supercritical : Criticality::subcritical);
    EXPECT_NE(to_text(nf, "p").find(s < 0 ? "period_doubling, supercritical (c = 6.28" : "subcritical (c = -6.28"),
              std::string::npos)
        << to_text(nf, "p");
    // mu = -e^{2 pi p}: mu_p = -2 pi (second differences, 1e-5 relative); the doubled orbit u1^2 = -p / s, so
    // |x0 - x0*| = |p|^(1/2) on the side -s.
    EXPECT_NEAR(nf.coefficient("mu_p"), -kTwoPi, 1e-4);
    EXPECT_NEAR(nf.amplitude, 1, 1e-3);
    EXPECT_EQ(nf.side, -s);
  }
}

// The pitch-flip seen through a near-identity change about its orbit: x = x_p(t) + h(z - x_p(t)), h(e) = e + Q(e),
// Q(e) = (k1 e1^2, k2 e1 e2) (t-independent, so z' stays 2 pi-periodic). The period maps are conjugate by h, whose
// linear part is I, so c = -2 pi s is unchanged while B(q, q) and the quadratic term of c are no longer zero.
class BentPitchFlip final : public ForcedSystem {
 public:
  explicit BentPitchFlip(double cubic) : base_(cubic) {}
  Eigen::Index dimension() const override { return 2; }
  static Eigen::Matrix2d DQ(const Eigen::Vector2d& e) {
    Eigen::Matrix2d D;
    D << 2 * kK1 * e[0], 0, kK2 * e[1], kK2 * e[0];
    return D;
  }
  // e = z - x_p(t), x = x_p + e + Q(e), K = I + DQ(e); e' = K^-1 (f(t, x) - x_p').
  struct At {
    Eigen::Vector2d x, de;
    Eigen::Matrix2d Ki;
  };
  At at(double t, std::span<const double> z, double p) const {
    const Eigen::Vector2d e = Eigen::Vector2d(z[0], z[1]) - ForcedPitchFlip::xp(t);
    At a;
    a.x = ForcedPitchFlip::xp(t) + e + Eigen::Vector2d(kK1 * e[0] * e[0], kK2 * e[0] * e[1]);
    a.Ki = (Eigen::Matrix2d::Identity() + DQ(e)).inverse();
    Eigen::Vector2d f;
    base_.rhs(t, std::span<const double>(a.x.data(), 2), p, std::span<double>(f.data(), 2));
    a.de = a.Ki * (f - ForcedPitchFlip::xp_dot(t));
    return a;
  }
  void rhs(double t, std::span<const double> z, double p, std::span<double> out) const override {
    Eigen::Map<Eigen::Vector2d>(out.data()) = ForcedPitchFlip::xp_dot(t) + at(t, z, p).de;
  }
  // K e' = f - x_p' differentiated in e: DQ(de) e' + K de' = J_f K de, and DQ(de) e' = DQ(e') de.
  void jacobian(double t, std::span<const double> z, double p, Eigen::MatrixXd& J) const override {
    const At a = at(t, z, p);
    Eigen::MatrixXd Jf;
    base_.jacobian(t, std::span<const double>(a.x.data(), 2), p, Jf);
    J = a.Ki * (Jf * a.Ki.inverse() - DQ(a.de));
  }
  void parameter_derivative(double t, std::span<const double> z, double p, std::span<double> fp) const override {
    const At a = at(t, z, p);
    Eigen::Vector2d g;
    base_.parameter_derivative(t, std::span<const double>(a.x.data(), 2), p, std::span<double>(g.data(), 2));
    Eigen::Map<Eigen::Vector2d>(fp.data()) = a.Ki * g;
  }

  static constexpr double kK1 = 0.7, kK2 = -0.5;

 private:
  ForcedPitchFlip base_;
};

TEST(PeriodDoublingNormalForm, FlipCoefficientWithQuadraticTerms) {
  for (const double s : {-1.0, 1.0}) {
    std::string why;
    const std::optional<NormalForm> form = pitch_flip_pd_form(BentPitchFlip(s), why);
    ASSERT_TRUE(form.has_value()) << why;
    const NormalForm& nf = *form;
    EXPECT_NEAR(nf.coefficient("c"), -2 * kPi * s, 1e-4) << nf.note;
    EXPECT_EQ(nf.criticality, s < 0 ? Criticality::supercritical : Criticality::subcritical);
    EXPECT_NEAR(nf.coefficient("mu_p"), -kTwoPi, 1e-4);
    // The quadratic term is exercised: without it c would be off by far more than the bar.
    EXPECT_GT(std::abs(nf.coefficient("quadratic")), 0.1) << nf.coefficient("quadratic");
  }
}

// The PD's amplitude law against the switched doubled orbit: with u1' = p u1 - u1^3 - u1^5 the doubled orbit has
// u1^2 = (sqrt(1 + 4 p) - 1) / 2 = p - p^2 + ..., so the law |x0 - x0*| = |p|^(1/2) (amplitude 1) is off by ~p / 2
// relative: 5e-3 at p = 1e-2, 5e-5 at 1e-4. The switched branch ends exactly on its bound p_max.
TEST(PeriodDoublingNormalForm, AmplitudeLawMatchesTheDoubledOrbitBetterCloser) {
  const ForcedPitchFlip sys(-1, -1);
  OrbitOptions oo;
  oo.segments = 4;
  const PeriodicOrbitProblem pr(sys, oo);
  const Branch b = pitch_flip_branch(pr, pitch_flip_options());
  const SpecialPoint* pd = find_special_point(b, SpecialPointType::PD);
  ASSERT_NE(pd, nullptr) << b.message;
  ASSERT_TRUE(pd->normal_form.has_value());
  const NormalForm& nf = *pd->normal_form;
  EXPECT_NEAR(nf.amplitude, 1, 1e-3);  // c and mu_p do not see the quintic term
  EXPECT_EQ(nf.side, 1);
  std::vector<double> errors;
  for (const double dp : {1e-2, 1e-4}) {
    OrbitSwitchOptions so;
    so.orbit = oo;
    so.continuation = pitch_flip_options();
    so.continuation.p_max = dp;
    const OrbitSwitchResult r = switch_at(pr, b, *pd, so);
    ASSERT_TRUE(r.switched) << r.message;
    const BranchPoint& end = r.branch.points.back();
    ASSERT_NEAR(end.p, dp, 1e-12);
    const double u = std::sqrt((std::sqrt(1 + 4 * dp) - 1) / 2);
    EXPECT_NEAR((end.x.head(2) - pd->x.head(2)).norm(), u, 1e-9);  // the closed form
    errors.push_back(std::abs((end.x.head(2) - pd->x.head(2)).norm() / (nf.amplitude * std::sqrt(dp)) - 1));
  }
  // Measured 4.9e-3 and 5.1e-5 (the expansion's p / 2; the law's own amplitude is off by 5e-7). Bars: 2x and 20x
  // that, and a factor 30 of shrinkage (measured 97).
  EXPECT_LT(errors[0], 1e-2);
  EXPECT_LT(errors[1], 1e-3);
  EXPECT_LT(errors[1], errors[0] / 30) << errors[0] << " " << errors[1];
}

// The forced pitch-flip made autonomous (autonomised_fixture.hpp). Its field is a polynomial in (cos t, sin t):
// R(t/2) e1 e1^T R(t/2)^T = P = [[1 + c, s], [s, 1 - c]] / 2, R(t/2) e2 e2^T R(t/2)^T = I - P and u1 R(t/2) e1 = P e
// (e = x - x_p, u = R(t/2)^T e), so f = x_p' + W e / 2 + p P e - (I - P) e + s3 (e^T P e) P e, x_p = (c, s + 0.6 s c).
Eigen::Vector2d pitch_xp(double c, double s) { return {c, s + 0.6 * s * c}; }
Eigen::Vector2d pitch_xp_dot(double c, double s) { return {-s, c + 0.6 * (c * c - s * s)}; }
Autonomised::Field pitch_flip_field(double cubic) {
  return [cubic](const Eigen::VectorXd& x, double c, double s, double p) {
    Eigen::Matrix2d P, W;
    P << 1 + c, s, s, 1 - c;
    P /= 2;
    W << 0, -1, 1, 0;
    const Eigen::Vector2d e = x - pitch_xp(c, s), Pe = P * e;
    return Eigen::VectorXd(pitch_xp_dot(c, s) + W * e / 2 + p * Pe - (e - Pe) + cubic * e.dot(Pe) * Pe);
  };
}
Autonomised autonomous_pitch_flip(double cubic) { return Autonomised(2, pitch_flip_field(cubic)); }
// BentPitchFlip's change about the orbit (x = x_p + e + Q(e), e' = K^-1 (f(x) - x_p')) on the autonomised field.
Autonomised autonomous_bent_pitch_flip(double cubic) {
  return Autonomised(2, [base = pitch_flip_field(cubic)](const Eigen::VectorXd& z, double c, double s, double p) {
    const Eigen::Vector2d xp = pitch_xp(c, s), xp_dot = pitch_xp_dot(c, s), e = Eigen::Vector2d(z[0], z[1]) - xp;
    const Eigen::Vector2d x =
        xp + e + Eigen::Vector2d(BentPitchFlip::kK1 * e[0] * e[0], BentPitchFlip::kK2 * e[0] * e[1]);
    const Eigen::Matrix2d Ki = (Eigen::Matrix2d::Identity() + BentPitchFlip::DQ(e)).inverse();
    return Eigen::VectorXd(xp_dot + Ki * (base(x, c, s, p) - xp_dot));
  });
}

TEST(AutonomisedPitchFlip, FieldIsTheForcedOneOnTheCircle) {
  const ForcedPitchFlip forced(-1);
  const Autonomised sys = autonomous_pitch_flip(-1);
  for (const double t : {0.3, 2.0, 3.5, 5.9}) {
    const Eigen::Vector2d x(0.7, -0.4);
    Eigen::Vector2d ff;
    forced.rhs(t, std::span<const double>(x.data(), 2), 0.3, std::span<double>(ff.data(), 2));
    const Eigen::VectorXd y = Autonomised::state(x, t);
    Eigen::Vector4d fa;
    sys.rhs(std::span<const double>(y.data(), 4), 0.3, std::span<double>(fa.data(), 4));
    EXPECT_NEAR((fa.head<2>() - ff).norm(), 0, 1e-13) << t;
    EXPECT_NEAR((fa.tail<2>() - Eigen::Vector2d(-std::sin(t), std::cos(t))).norm(), 0, 1e-15);
  }
}

// The PD of the autonomised pitch-flip's orbit branch (orbit x_p, period 2 pi; phase: c is extremal at t = 0), its
// normal form attached by the engine, against the closed form and the forced system's period-map normal form. The
// section S through x0* = (x_p(0), 1, 0) has the normal f(x0*) ~ (0, 1.6, 0, 1), and the doubled orbit
// x_p(t) +- sqrt(p) R(t/2) e1 crosses it at t = 0 in x_p(0) +- sqrt(p) e1: |x0 - x0*| = sqrt(p) exactly, the
// amplitude law's 1 (side -s3).
TEST(AutonomousOrbitNormalForm, PeriodDoublingAgainstTheClosedFormAndTheForcedMap) {
  for (const double s3 : {-1.0, 1.0}) {
    const Autonomised sys = autonomous_pitch_flip(s3);
    const AutonomousOrbitProblem pr(sys, 2, four_segment_orbit());
    const Eigen::VectorXd x0 = Autonomised::state(ForcedPitchFlip::xp(0), 0);
    const Branch b = continue_branch(pr, pr.shooting_guess(x0, kTwoPi, -0.2), -0.2, pitch_flip_options());
    const SpecialPoint* pd = find_special_point(b, SpecialPointType::PD);
    ASSERT_NE(pd, nullptr) << b.message;
    EXPECT_NEAR(pd->p, 0, 1e-8);
    ASSERT_TRUE(pd->normal_form.has_value());
    const NormalForm& nf = *pd->normal_form;
    EXPECT_EQ(nf.kind, NormalFormKind::period_doubling);
    EXPECT_EQ(nf.criticality, s3 < 0 ? Criticality::supercritical : Criticality::subcritical) << nf.note;
    // Measured 1 + 7.0e-7 (c = +-6.2831765, mu_p = -2 pi to 3e-9: the forced map's numbers); bar 1e-5.
    EXPECT_NEAR(nf.amplitude, 1, 1e-5) << nf.note;
    EXPECT_EQ(nf.side, -s3);
    EXPECT_NEAR(nf.coefficient("mu_p"), -kTwoPi, 1e-6);  // the multiplier -e^{2 pi p}
    // Another method: the forced period map's normal form of the same system (invariants: the law, the side, the
    // criticality and the multiplier's derivative).
    std::string why;
    const std::optional<NormalForm> forced = pitch_flip_pd_form(ForcedPitchFlip(s3), why);
    ASSERT_TRUE(forced.has_value()) << why;
    EXPECT_NEAR(nf.amplitude, forced->amplitude, 1e-5);
    EXPECT_EQ(nf.side, forced->side);
    EXPECT_EQ(nf.criticality, forced->criticality);
    EXPECT_NEAR(nf.coefficient("mu_p"), forced->coefficient("mu_p"), 1e-6);
    // A wrong sign of c moves the law to the other side and flips the criticality: the checks above fail for it (the
    // loop's other s3 is that case).
  }
  // The oracle itself: at p = 1e-2 the section point x0* + sqrt(p) e1 returns to itself after 4 pi (the doubled
  // orbit, exact to the integration's ~1e-11) but not after 2 pi.
  const Autonomised sys = autonomous_pitch_flip(-1);
  const AutonomousOrbitProblem pr(sys, 2, four_segment_orbit());
  const Eigen::VectorXd y = Autonomised::state(ForcedPitchFlip::xp(0) + Eigen::Vector2d(0.1, 0), 0);
  EXPECT_LT((pr.flow(y, 4 * kPi, 1e-2) - y).norm(), 1e-9);
  EXPECT_GT((pr.flow(y, kTwoPi, 1e-2) - y).norm(), 0.1);
}

// With quadratic terms (the bent pitch-flip made autonomous, at its PD orbit x_p, p = 0): the change has linear part I
// and leaves f(x0*) and the section as they were, so c = -2 pi s and the law's 1 hold as above, while B(q, q) != 0
// now: the cubic term alone would move the law far off (the check can fail on a dropped term).
TEST(AutonomousOrbitNormalForm, PeriodDoublingWithQuadraticTerms) {
  for (const double s3 : {-1.0, 1.0}) {
    const Autonomised sys = autonomous_bent_pitch_flip(s3);
    const AutonomousOrbitProblem pr(sys, 2, four_segment_orbit());
    const Eigen::VectorXd x0 = Autonomised::state(ForcedPitchFlip::xp(0), 0);
    const NormalForm nf = period_doubling_normal_form(pr, pr.shooting_guess(x0, kTwoPi, 0), 0);
    EXPECT_EQ(nf.criticality, s3 < 0 ? Criticality::supercritical : Criticality::subcritical) << nf.note;
    EXPECT_NEAR(nf.coefficient("c"), -kTwoPi * s3, 1e-4) << nf.note;
    // Measured c = 6.2831867 (4.3232 + 1.9600) and -6.2831551 (-8.2432 + 1.9600), the forced map's numbers; the
    // amplitude 1 - 1.1e-7 and 1 + 2.4e-6 (bar 1e-5); the cubic term alone gives 1.206 and 0.873.
    EXPECT_NEAR(nf.amplitude, 1, 1e-5);
    EXPECT_EQ(nf.side, -s3);
    EXPECT_GT(std::abs(nf.coefficient("quadratic")), 0.1) << nf.coefficient("quadratic");
    EXPECT_GT(std::abs(std::sqrt(std::abs(nf.coefficient("mu_p") / nf.coefficient("cubic"))) - 1), 0.1);
  }
}

// The PD switch on an autonomous orbit branch: the autonomised pitch-flip's doubled orbit (period 4 pi, 8 segments)
// against its closed form x_p(t) +- sqrt(p) R(t/2) e1, (c, s) = (cos t, sin t) with t = t0 + pi j / 2 at segment j,
// t0 the doubled orbit's phase (the phase condition c' = 0: t0 = 0 or pi); Newton starts where the PD's law puts
// the predictor's distance (predicted_p = eps^2 = 1e-6).
TEST(PeriodDoublingSwitch, AutonomousDoubledOrbitInClosedForm) {
  const Autonomised sys = autonomous_pitch_flip(-1);
  const AutonomousOrbitProblem pr(sys, 2, four_segment_orbit());
  const Eigen::VectorXd x0 = Autonomised::state(ForcedPitchFlip::xp(0), 0);
  const Branch b = continue_branch(pr, pr.shooting_guess(x0, kTwoPi, -0.2), -0.2, pitch_flip_options());
  const SpecialPoint* pd = find_special_point(b, SpecialPointType::PD);
  ASSERT_NE(pd, nullptr) << b.message;
  OrbitSwitchOptions so;
  so.orbit = four_segment_orbit();
  so.continuation = pitch_flip_options();
  so.continuation.max_points = 30;
  const OrbitSwitchStart start = orbit_switch_start(pr, b, *pd, so);
  ASSERT_TRUE(start.found) << start.message;
  EXPECT_NEAR(start.predicted_p, 1e-6, 1e-10);
  const OrbitSwitchResult r = switch_at(pr, b, *pd, so);
  ASSERT_TRUE(r.switched) << r.message;
  EXPECT_NEAR(r.period, 4 * kPi, 1e-10);
  const auto* doubled = dynamic_cast<const AutonomousOrbitProblem*>(r.problem.get());
  ASSERT_NE(doubled, nullptr);
  EXPECT_EQ(doubled->segments(), 8);
  ASSERT_GE(r.branch.points.size(), 5u);
  EXPECT_NEAR(r.branch.points.back().p, 0.2, 1e-12);
  for (const BranchPoint& pt : r.branch.points) {
    EXPECT_NEAR(AutonomousOrbitProblem::period(pt.x), 4 * kPi, 1e-9);
    const double t0 = pt.x[2] > 0 ? 0 : kPi, amp = std::sqrt(pt.p);
    const double sign = (pt.x.head(2) - ForcedPitchFlip::xp(t0)).dot(ForcedPitchFlip::R(t0).col(0)) > 0 ? 1 : -1;
    for (int j = 0; j < 8; ++j) {
      const double t = t0 + kPi * j / 2;
      const Eigen::VectorXd expected =
          Autonomised::state(ForcedPitchFlip::xp(t) + sign * amp * ForcedPitchFlip::R(t).col(0), t);
      EXPECT_NEAR((pt.x.segment(4 * j, 4) - expected).norm(), 0, 1e-9) << pt.p << " " << j;
    }
    EXPECT_TRUE(pt.stable);
  }
  // A point of the branch that is not a PD is refused naming its multipliers.
  SpecialPoint not_pd = *pd;
  not_pd.x = b.points.front().x;
  not_pd.p = b.points.front().p;
  EXPECT_NE(switch_at(pr, b, not_pd, so).message.find("not a simple period doubling"), std::string::npos);
}

TEST(PeriodDoublingSwitch, RejectsBadPeriods) {
  const ForcedPitchFlip sys;
  EXPECT_THROW(PeriodicOrbitProblem(sys, {}, 0), InvalidArgument);
  OrbitSwitchOptions so;
  so.amplitude = 0;
  EXPECT_THROW(so.validate(), InvalidArgument);
}

// The diagram's dispatch (grow_tree with default_switchers): the HB of the skewed subcritical normal form starts its
// orbit branch as a child with its own problem, every point on the closed form, and the first point where the HB's
// normal form puts it: p - p_HB = side (peak / amplitude)^2 for the predictor's peak (measured 4.7e-10 relative;
// bar 1e-6, l1 comes from finite differences to ~1e-7), the first point itself on the closed form a(rho) = 0.
TEST(OrbitTree, HopfPointStartsTheOrbitBranchInTheTree) {
  Eigen::MatrixXd A(3, 3);
  A << 1, 0.5, 0.2, 0.3, 1, -0.4, 0.1, 0.2, 2;
  const HopfNormalForm sys(1, 0, 0.7, A);
  const AutonomousEquilibriumProblem eq(sys);
  const Branch e = equilibrium_branch(eq);
  const SpecialPoint* hb = find_special_point(e, SpecialPointType::HB);
  ASSERT_NE(hb, nullptr);
  ASSERT_TRUE(hb->normal_form.has_value());
  EXPECT_EQ(hb->normal_form->side, -1);  // subcritical: the orbits lie below the HB
  OrbitSwitchOptions so = switch_options(-0.5, 1);
  const OrbitSwitchStart s = orbit_switch_start(eq, e, *hb, so);
  ASSERT_TRUE(s.found) << s.message;
  ASSERT_TRUE(std::isfinite(s.predicted_p));
  const double rho = sys.x_of(s.x.head(3)).head(2).squaredNorm();
  EXPECT_NEAR(s.p, -rho, 1e-12);  // on the closed form a(rho) = p + rho = 0
  EXPECT_LT(s.predicted_p - hb->p, 0);
  EXPECT_NEAR((s.p - hb->p) / (s.predicted_p - hb->p), 1, 1e-6) << s.p << " " << s.predicted_p;
  EXPECT_EQ(s.away, Direction::backward);

  TreeOptions o;
  o.depth = 2;
  o.switching.amplitude = so.amplitude;
  o.switching.continuation = so.continuation;
  o.switchers = default_switchers(so.orbit);
  const BranchTree t = grow_tree(eq, e, o);
  ASSERT_EQ(t.branches.size(), 2u);
  const TreeBranch& c = t.branches[1];
  EXPECT_EQ(c.parent, 0);
  EXPECT_EQ(c.side, 1);
  ASSERT_NE(c.problem, nullptr);
  EXPECT_NE(dynamic_cast<const AutonomousOrbitProblem*>(c.problem.get()), nullptr);
  EXPECT_NEAR(c.branch.points.back().p, -0.5, 1e-12);
  expect_closed_form(sys, c.branch, 1, 0, 0.7);
  ASSERT_EQ(t.emanations.size(), 1u);  // the HB; the orbit branch has no branching point
  EXPECT_EQ(t.emanations[0].outcome, EmanationOutcome::followed);
  EXPECT_EQ(t.emanations[0].branch_to, 1);
}

// The diagram's dispatch carries the Poincare map's normal forms: the skewed fold-of-cycles system's HB starts its
// orbit branch in the tree, and that branch's LPC label has the fold with the closed-form law at its located point,
// in the branch's JSON and text too.
TEST(OrbitTree, AutonomousOrbitBranchCarriesItsFoldOfCycles) {
  const HopfNormalForm sys(1, -1, 1.0, kSkew);
  const AutonomousEquilibriumProblem eq(sys);
  const Branch e = equilibrium_branch(eq);
  const OrbitSwitchOptions so = switch_options(-1, 0.2);
  TreeOptions o;
  o.depth = 2;
  o.switching.amplitude = so.amplitude;
  o.switching.continuation = so.continuation;
  o.switchers = default_switchers(so.orbit);
  const BranchTree t = grow_tree(eq, e, o);
  ASSERT_EQ(t.branches.size(), 2u);
  const Branch& b = t.branches[1].branch;
  const SpecialPoint* lpc = find_special_point(b, SpecialPointType::LPC);
  ASSERT_NE(lpc, nullptr) << b.message;
  ASSERT_TRUE(lpc->normal_form.has_value());
  const NormalForm& nf = *lpc->normal_form;
  EXPECT_EQ(nf.criticality, Criticality::not_applicable) << nf.note;
  const double law = fold_law(sys, lpc->x.head(3));
  EXPECT_NEAR(nf.amplitude, law, 1e-5 * law) << nf.note;  // as at the exact fold (bar: second differences)
  EXPECT_EQ(nf.side, 1);
  MeasuredBranch m;
  m.branch = b;
  m.spectrum_kind = StabilityKind::multipliers;
  m.point_measures.assign(b.points.size(), {});
  m.special_measures.assign(b.special_points.size(), {});
  const nlohmann::json j = to_json(m);
  bool found = false;
  for (const auto& sp : j["special_points"])
    if (sp["type"] == "LPC") {
      found = true;
      EXPECT_EQ(sp["normal_form"]["kind"], "fold_of_cycles");
      EXPECT_EQ(sp["normal_form"]["amplitude"].get<double>(), nf.amplitude);
    }
  EXPECT_TRUE(found) << j["special_points"].dump();
  EXPECT_NE(to_text(nf, "p").find("fold_of_cycles (p2 = "), std::string::npos) << to_text(nf, "p");
}

// The forced system's PD through the tree: the doubled orbit is a child with its own problem (2 periods, 8
// segments), on the closed form x_p(t) +- sqrt(p) R(t/2) e_1 at every segment start.
TEST(OrbitTree, PeriodDoublingStartsTheDoubledOrbitInTheTree) {
  const ForcedPitchFlip sys;
  OrbitOptions oo;
  oo.segments = 4;
  const PeriodicOrbitProblem pr(sys, oo);
  const ContinuationOptions co = pitch_flip_options();
  const Branch b = pitch_flip_branch(pr, co);
  TreeOptions o;
  o.depth = 3;
  o.switching.continuation = co;
  o.switching.continuation.max_points = 30;
  const BranchTree t = grow_tree(pr, b, o);
  ASSERT_EQ(t.branches.size(), 2u);
  const auto* doubled = dynamic_cast<const PeriodicOrbitProblem*>(t.branches[1].problem.get());
  ASSERT_NE(doubled, nullptr);
  EXPECT_EQ(doubled->periods(), 2);
  EXPECT_EQ(doubled->segments(), 8);
  const Branch& c = t.branches[1].branch;
  ASSERT_GE(c.points.size(), 5u);
  EXPECT_NEAR(c.points.back().p, 0.2, 1e-12);
  for (const BranchPoint& pt : c.points) {
    const double sign = pt.x[0] > ForcedPitchFlip::xp(0)[0] ? 1 : -1;
    for (int j = 0; j < 8; ++j) {
      const double tj = kPi * j / 2;
      const Eigen::Vector2d expected = ForcedPitchFlip::xp(tj) + sign * std::sqrt(pt.p) * ForcedPitchFlip::R(tj).col(0);
      EXPECT_NEAR((pt.x.segment(2 * j, 2) - expected).norm(), 0, 1e-9) << pt.p << " " << j;
    }
  }
  ASSERT_EQ(t.emanations.size(), 1u);
  EXPECT_EQ(t.emanations[0].outcome, EmanationOutcome::followed);
}

// u' = (1 - p^2 - |u|^2) u + omega R u seen in x = D u, D = diag(2, 1) (so the Hopf vector's largest component, the
// orbit problem's phase component, is the same at both HBs): the equilibrium x = 0 has HBs at p = -1 and p = 1, and
// one family of orbits |u|^2 = 1 - p^2 (period 2 pi / omega) joins them.
class TwoHopfs final : public AutonomousSystem {
 public:
  static constexpr double kW = 1.5;
  Eigen::Index dimension() const override { return 2; }
  void rhs(std::span<const double> x, double p, std::span<double> f) const override {
    const Eigen::Vector2d u(x[0] / 2, x[1]);
    const double a = 1 - p * p - u.squaredNorm();
    f[0] = 2 * (a * u[0] - kW * u[1]);
    f[1] = kW * u[0] + a * u[1];
  }
  void jacobian(std::span<const double> x, double p, Eigen::MatrixXd& J) const override {
    const Eigen::Vector2d u(x[0] / 2, x[1]);
    const double a = 1 - p * p - u.squaredNorm();
    Eigen::Matrix2d Ju, D = Eigen::Vector2d(2, 1).asDiagonal();
    Ju << a, -kW, kW, a;
    Ju -= 2 * u * u.transpose();
    J = D * Ju * D.inverse();
  }
  void parameter_derivative(std::span<const double> x, double p, std::span<double> fp) const override {
    fp[0] = -2 * p * x[0];
    fp[1] = -2 * p * x[1];
  }
};

// Of the start branch's two HBs, one starts the orbit branch (branch 1) and the other's start is its duplicate.
void expect_one_followed_and_one_duplicate_of_it(const BranchTree& t) {
  int followed = 0, duplicate = 0;
  for (const TreeEmanation& m : t.emanations) {
    if (m.branch != 0) continue;
    followed += m.outcome == EmanationOutcome::followed;
    if (m.outcome == EmanationOutcome::duplicate) {
      ++duplicate;
      EXPECT_EQ(m.branch_to, 1);
    }
  }
  EXPECT_EQ(followed, 1);
  EXPECT_EQ(duplicate, 1);
}

// The orbit branch from the first HB reaches the second one: the second HB's start lies on it (each switch built its
// own orbit problem, on the same equations), so it is marked a duplicate of that branch and not followed again.
TEST(OrbitTree, OrbitBranchJoiningTwoHopfPointsIsFollowedOnce) {
  const TwoHopfs sys;
  const AutonomousEquilibriumProblem eq(sys);
  ContinuationOptions co;
  co.p_min = -2;
  co.p_max = 2;
  co.max_step = 0.2;
  const Branch e = continue_branch(eq, Eigen::Vector2d::Zero(), -2, co);
  int hbs = 0;
  for (const SpecialPoint& sp : e.special_points) hbs += sp.type == SpecialPointType::HB;
  ASSERT_EQ(hbs, 2);
  OrbitOptions oo;
  oo.segments = 4;
  TreeOptions o;
  o.depth = 2;
  o.switching.continuation = co;
  o.switching.continuation.max_points = 200;
  o.switchers = default_switchers(oo);
  const BranchTree t = grow_tree(eq, e, o);
  ASSERT_EQ(t.branches.size(), 2u) << t.branches.back().branch.message;
  const Branch& orbit = t.branches[1].branch;
  for (const BranchPoint& pt : orbit.points) {
    const Eigen::Vector2d u(pt.x[0] / 2, pt.x[1]);
    EXPECT_NEAR(u.squaredNorm(), 1 - pt.p * pt.p, 1e-8) << pt.p;
  }
  expect_one_followed_and_one_duplicate_of_it(t);
}

// TwoHopfs seen through x = D(p) u, D(p) = diag(1.5 - p / 2, 1.5 + p / 2): diag(2, 1) at the HB p = -1 and diag(1, 2)
// at p = 1, so the two HB switches pick different phase components (the Hopf vector's largest: x_0, then x_1) and
// build orbit problems that represent the one joining family differently.
class TwoHopfsTurning final : public AutonomousSystem {
 public:
  static Eigen::Vector2d d(double p) { return {1.5 - p / 2, 1.5 + p / 2}; }
  Eigen::Index dimension() const override { return 2; }
  void rhs(std::span<const double> x, double p, std::span<double> f) const override {
    const Eigen::Vector2d u(x[0] / d(p)[0], x[1] / d(p)[1]);
    const Eigen::Vector2d g = g_of(u, p);
    f[0] = d(p)[0] * g[0];
    f[1] = d(p)[1] * g[1];
  }
  void jacobian(std::span<const double> x, double p, Eigen::MatrixXd& J) const override {
    const Eigen::Vector2d u(x[0] / d(p)[0], x[1] / d(p)[1]);
    const Eigen::Matrix2d D = d(p).asDiagonal();
    J = D * jg(u, p) * D.inverse();
  }
  void parameter_derivative(std::span<const double> x, double p, std::span<double> fp) const override {
    // f = D g(D^-1 x, p): f_p = D' g + D (J_g du/dp + g_p), du/dp = -D^-1 D' u, g_p = -2 p u.
    const Eigen::Vector2d u(x[0] / d(p)[0], x[1] / d(p)[1]);
    const Eigen::Matrix2d D = d(p).asDiagonal(), Dp = Eigen::Vector2d(-0.5, 0.5).asDiagonal();
    const Eigen::Vector2d r = Dp * g_of(u, p) + D * (jg(u, p) * (-D.inverse() * Dp * u) - 2 * p * u);
    fp[0] = r[0];
    fp[1] = r[1];
  }

 private:
  static Eigen::Vector2d g_of(const Eigen::Vector2d& u, double p) {
    const double a = 1 - p * p - u.squaredNorm();
    return {a * u[0] - TwoHopfs::kW * u[1], TwoHopfs::kW * u[0] + a * u[1]};
  }
  static Eigen::Matrix2d jg(const Eigen::Vector2d& u, double p) {
    const double a = 1 - p * p - u.squaredNorm();
    Eigen::Matrix2d J;
    J << a, -TwoHopfs::kW, TwoHopfs::kW, a;
    return J - 2 * u * u.transpose();
  }
};

// The joining family is found once although the second HB's start is in another phase representation (extremum of
// x_1, not x_0): it is mapped onto the first problem's (re-phased) before it is compared, and marked a duplicate.
TEST(OrbitTree, JoiningFamilyInAnotherPhaseRepresentationIsFollowedOnce) {
  const TwoHopfsTurning sys;
  const AutonomousEquilibriumProblem eq(sys);
  ContinuationOptions co;
  co.p_min = -2;
  co.p_max = 2;
  co.max_step = 0.2;
  const Branch e = continue_branch(eq, Eigen::Vector2d::Zero(), -2, co);
  std::vector<const SpecialPoint*> hbs;
  for (const SpecialPoint& sp : e.special_points)
    if (sp.type == SpecialPointType::HB) hbs.push_back(&sp);
  ASSERT_EQ(hbs.size(), 2u);
  OrbitOptions oo;
  oo.segments = 4;
  // The set-up: the two switches pick components 0 and 1.
  OrbitSwitchOptions so;
  so.orbit = oo;
  so.continuation = co;
  int components[2] = {-1, -1};
  for (std::size_t k = 0; k < 2; ++k) {
    const OrbitSwitchStart s = orbit_switch_start(eq, e, *hbs[k], so);
    ASSERT_TRUE(s.found) << s.message;
    components[k] = dynamic_cast<const AutonomousOrbitProblem&>(*s.problem).phase_component();
  }
  EXPECT_NE(components[0], components[1]);
  TreeOptions o;
  o.depth = 2;
  o.switching.continuation = co;
  o.switching.continuation.max_points = 200;
  o.switchers = default_switchers(oo);
  const BranchTree t = grow_tree(eq, e, o);
  ASSERT_EQ(t.branches.size(), 2u) << t.branches.back().branch.message;
  for (const BranchPoint& pt : t.branches[1].branch.points) {
    const Eigen::Vector2d u(pt.x[0] / TwoHopfsTurning::d(pt.p)[0], pt.x[1] / TwoHopfsTurning::d(pt.p)[1]);
    EXPECT_NEAR(u.squaredNorm(), 1 - pt.p * pt.p, 1e-8) << pt.p;
  }
  expect_one_followed_and_one_duplicate_of_it(t);
}

// A double Hopf point in the tree: not followed, the reason named (both pairs), and not a failure.
TEST(OrbitTree, MultipleHopfIsListedWithTheReason) {
  const DoubleHopf sys;
  const AutonomousEquilibriumProblem eq(sys);
  ContinuationOptions co;
  co.p_min = -0.3;
  co.p_max = 0.3;
  co.max_step = 0.1;
  const Branch e = continue_branch(eq, Eigen::VectorXd::Zero(4), -0.3, co);
  ASSERT_NE(find_special_point(e, SpecialPointType::HB), nullptr);
  TreeOptions o;
  o.switching.continuation = co;
  const BranchTree t = grow_tree(eq, e, o);
  EXPECT_EQ(t.branches.size(), 1u);
  ASSERT_FALSE(t.emanations.empty());
  for (const TreeEmanation& m : t.emanations) {
    if (m.outcome == EmanationOutcome::already_switched) continue;  // the second pair's HB at the same point
    EXPECT_EQ(m.outcome, EmanationOutcome::not_available);
    EXPECT_EQ(m.side, 0);
    EXPECT_NE(m.message.find("not a simple Hopf point"), std::string::npos) << m.message;
    EXPECT_NE(m.message.find("2i"), std::string::npos) << m.message;
  }
}

// This model's l >= 3 onset (full model, L = 4, C from 0.08 down): every HB there is the pair i m/2 of an unforced
// l-block crossing with its BP (l, m = 0). The switch says what is born there: the BP branch's states with the block
// turned into mode m, rotating at m/2 (model/rotating_wave.hpp, checked against simulation in rotating_wave_test),
// naming the BP; the eigenvalues on the axis are exactly the block's 0 and i m/2 (no other pair: the l = 2, m = 1
// pair is Upsilon_2(sigma_l^c) +- i/2 with Upsilon_2 < 0 here). Failing case: a simple HB of a problem kind without a
// switch keeps the old refusal (the same point with its modes removed is no rotating-wave onset).
TEST(HopfSwitch, FullModelOnsetHBsAreRotatingWavesOfTheBPBranch) {
  const Scene scene = modal_fixtures::scene(0.08, 4);
  const BranchSpec spec =
      test::spec_of(scene, ProblemKind::full, ContinuationParameter::C, 0.02, 0.08, Direction::backward);
  const Branch b = continue_scene(spec).branch.branch;
  const FullEquilibriumProblem problem(scene, ContinuationParameter::C);
  int hbs = 0;
  for (const SpecialPoint& sp : b.special_points) {
    if (sp.type != SpecialPointType::HB) continue;
    ++hbs;
    ASSERT_TRUE(sp.mode_l && sp.mode_m);
    const int l = *sp.mode_l, m = *sp.mode_m;
    const OrbitSwitchResult r = switch_at(problem, b, sp);
    EXPECT_FALSE(r.switched);
    ASSERT_GE(r.rotating_wave_of, 0) << r.message;
    const SpecialPoint& bp = b.special_points[static_cast<std::size_t>(r.rotating_wave_of)];
    EXPECT_EQ(bp.type, SpecialPointType::BP);
    EXPECT_EQ(bp.mode_l, l);
    EXPECT_EQ(bp.mode_m, 0);
    for (const std::string& part : std::vector<std::string>{
             "the onset of the unforced l = " + std::to_string(l) + " block",
             "BP (l = " + std::to_string(l) + ", m = 0)", "turned into mode m = " + std::to_string(m),
             "period 4 pi/m = " + format_value(4 * kPi / m), "not followed as separate branches",
             "stability is not computed"})
      EXPECT_NE(r.message.find(part), std::string::npos) << part << " in " << r.message;
    // On the axis: 0 and i m'/2, m' = 1..l, once each.
    const Eigen::VectorXcd ev = problem.spectrum(sp.x, sp.p);
    int on_axis = 0;
    for (const std::complex<double>& z : ev) on_axis += std::abs(z.real()) < 1e-6 && z.imag() >= 0;
    EXPECT_EQ(on_axis, l + 1);
    const Parameters q = with_parameter(scene.parameters, ContinuationParameter::C, sp.p);
    EXPECT_LT(Upsilon_l(q, 2, sigma_c(l, q.alpha())), -1e-2);  // the l = 2, m = 1 pair is damped
    SpecialPoint bare = sp;
    bare.mode_l.reset();
    EXPECT_EQ(switch_at(problem, b, bare).rotating_wave_of, -1);
    EXPECT_NE(switch_at(problem, b, bare).message.find("a multiple Hopf point"), std::string::npos);
  }
  EXPECT_EQ(hbs, 3 + 4);
}

// At Delta0 = 0 (lambda = 5, C = 0.04, L = 4; the scene of BranchPointMode.HopfPairCoincidingWithANeutralPair...) the
// l = 2, m = 1 pair sits on the axis at i/2 all along the branch in B: with no rest shape nothing drives f_{2,0} or
// f_{2,+-1}, and the state's f_{2,0} != 0 pins sigma = sigma_2^c (Upsilon_2 = 0), so that pair, Upsilon_2 +- i/2,
// is neutral exactly (the same rotating-frame argument turns the l = 2 tilt f_{2,0} into f_{2,+-1} rotating at 1/2).
// At B = 0.72 (sigma_3^c = sigma_2^c) the l = 3 onset's m = 1 pair crosses at the same i/2: its HB is still the l = 3
// block's rotating wave (its BP named), with 0.5i listed twice.
TEST(HopfSwitch, AtDelta0ZeroTheL2M1PairIsNeutralBecauseSigmaIsPinned) {
  Scene scene;
  scene.parameters.Delta0 = 0;
  scene.parameters.B = 1.5;
  scene.L = 4;
  const Branch b =
      continue_scene(test::spec_of(scene, ProblemKind::full, ContinuationParameter::B, 0.5, 1.5, Direction::backward))
          .branch.branch;
  const FullEquilibriumProblem problem(scene, ContinuationParameter::B);
  ASSERT_GE(b.points.size(), 5u);
  for (std::size_t k = 0; k < b.points.size(); k += b.points.size() / 5) {
    const BranchPoint& pt = b.points[k];
    const Parameters q = with_parameter(scene.parameters, ContinuationParameter::B, pt.p);
    EXPECT_NEAR(problem.observe(pt.x, pt.p).sigma, sigma_c(2, q.alpha()), 1e-9 * std::abs(sigma_c(2, q.alpha())));
    EXPECT_GT(std::abs(pt.x[FullEquilibriumProblem::index(2, 0)]), 1e-3);
    const Eigen::VectorXcd ev = problem.spectrum(pt.x, pt.p);
    double nearest = 1;
    for (const std::complex<double>& z : ev) nearest = std::min(nearest, std::abs(z - std::complex<double>(0, 0.5)));
    EXPECT_LT(nearest, 1e-9) << "B = " << pt.p;
  }
  for (const SpecialPoint& sp : b.special_points)
    if (sp.type == SpecialPointType::HB && sp.mode_l == 3 && sp.mode_m == 1) {
      const OrbitSwitchResult r = switch_at(problem, b, sp);
      EXPECT_GE(r.rotating_wave_of, 0) << r.message;
      int halves = 0;
      for (std::size_t at = r.message.find("+ 0.5i"); at != std::string::npos; at = r.message.find("+ 0.5i", at + 1))
        ++halves;
      EXPECT_EQ(halves, 2) << r.message;  // l = 2's and l = 3's m = 1 pairs
    }
}

// In a tree (the diagram's core) each HB of the l = 3 onset is a rotating_wave entry, side 0, pointing at the BP
// (point_to) and at the branch followed from it (branch_to, whose parent point is that BP).
TEST(OrbitTree, FullModelOnsetHBsPointAtTheBranchFromTheirBP) {
  const Scene scene = modal_fixtures::scene(0.08, 4);
  const Branch b =
      continue_scene(test::spec_of(scene, ProblemKind::full, ContinuationParameter::C, 0.03, 0.08, Direction::backward))
          .branch.branch;
  const FullEquilibriumProblem problem(scene, ContinuationParameter::C);
  TreeOptions o;
  o.switching.continuation.p_min = 0.03;
  o.switching.continuation.p_max = 0.08;
  o.switching.continuation.max_points = 20;
  const BranchTree t = grow_tree(problem, b, o);
  int waves = 0;
  for (const TreeEmanation& e : t.emanations) {
    if (e.branch != 0 || b.special_points[e.point].type != SpecialPointType::HB) continue;
    ++waves;
    EXPECT_EQ(e.outcome, EmanationOutcome::rotating_wave) << e.message;
    EXPECT_EQ(e.side, 0);
    ASSERT_GE(e.point_to, 0);
    EXPECT_EQ(b.special_points[static_cast<std::size_t>(e.point_to)].mode_l, 3);
    ASSERT_GE(e.branch_to, 1) << e.message;
    EXPECT_EQ(t.branches[static_cast<std::size_t>(e.branch_to)].parent_point, e.point_to);
  }
  EXPECT_EQ(waves, 3);
}

}  // namespace
}  // namespace rbcstab
