// Normal forms of forced orbits' period maps (period_map_normal_form.hpp) against closed forms: a fold of cycles
// (LPC) and a Neimark-Sacker point (NS) of forced systems x = x_p(t) + R(t) M y whose period map in y is the time-2 pi
// map of an autonomous normal form (R(t) the rotation by t, so R(2 pi) = I and the map in x0 is that map seen through
// M); for the NS the normal form is also seen through a quadratic near-identity change y -> u = y + Q(y), which
// leaves d unchanged and makes every term of its formula non-zero. The step convergence of the differences, the
// refusal of bad steps; the NS system made autonomous (its Poincare map's normal form).
#include <gtest/gtest.h>

#include "continuation/autonomised_fixture.hpp"

#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "rbcstab/continuation/autonomous_orbit.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/normal_form_analysis.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/period_map_normal_form.hpp"
#include "rbcstab/continuation/poincare_map.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {

// Not orthogonal (A != A^T in x), mixing the third component in.
const Eigen::Matrix3d kFrame = (Eigen::Matrix3d() << 1, 0.5, 0.2, 0.3, 1, -0.4, 0.1, 0.2, 2).finished();

// The autonomous part: y' = g(y, p) with its Jacobian and p-derivative.
struct Autonomous {
  std::function<Eigen::Vector3d(const Eigen::Vector3d&, double)> g;
  std::function<Eigen::Matrix3d(const Eigen::Vector3d&, double)> dg;
  std::function<Eigen::Vector3d(const Eigen::Vector3d&, double)> gp;
};

// x = x_p(t) + R(t) M y, y' = g(y, p): x' = x_p'(t) + R(t) (W M y + M g(y, p)), W = R^T R' (the quarter turn in the
// first two components). Every term is a polynomial in (c, s) = (cos t, sin t) (0.3 sin 2t = 0.6 s c): field(c, s)
// is also the autonomised system's (autonomised_fixture.hpp).
class RotatingFrame final : public ForcedSystem {
 public:
  explicit RotatingFrame(Autonomous a) : a_(std::move(a)), Mi_(kFrame.inverse()) {}
  static Eigen::Vector3d xp(double t) { return xp_of(std::cos(t), std::sin(t)); }
  static Eigen::Vector3d xp_of(double c, double s) { return {c, s + 0.6 * s * c, 0.2 * c}; }
  static Eigen::Vector3d xp_dot_of(double c, double s) { return {-s, c + 0.6 * (c * c - s * s), -0.2 * s}; }
  static Eigen::Matrix3d R(double t) { return R_of(std::cos(t), std::sin(t)); }
  static Eigen::Matrix3d R_of(double c, double s) {
    Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
    m.topLeftCorner<2, 2>() << c, -s, s, c;
    return m;
  }
  static Eigen::Matrix3d W() {
    Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
    m(0, 1) = -1;
    m(1, 0) = 1;
    return m;
  }
  Eigen::Vector3d y_of(double t, std::span<const double> x) const {
    return Mi_ * R(t).transpose() * (Eigen::Vector3d(x[0], x[1], x[2]) - xp(t));
  }
  Eigen::Vector3d field(double c, double s, const Eigen::Vector3d& x, double p) const {
    const Eigen::Vector3d y = Mi_ * R_of(c, s).transpose() * (x - xp_of(c, s));
    return xp_dot_of(c, s) + R_of(c, s) * (W() * kFrame * y + kFrame * a_.g(y, p));
  }
  Eigen::Index dimension() const override { return 3; }
  void rhs(double t, std::span<const double> x, double p, std::span<double> f) const override {
    Eigen::Map<Eigen::Vector3d>(f.data()) = field(std::cos(t), std::sin(t), Eigen::Vector3d(x[0], x[1], x[2]), p);
  }
  void jacobian(double t, std::span<const double> x, double p, Eigen::MatrixXd& J) const override {
    const Eigen::Vector3d y = y_of(t, x);
    J = R(t) * (W() + kFrame * a_.dg(y, p) * Mi_) * R(t).transpose();
  }
  void parameter_derivative(double t, std::span<const double> x, double p, std::span<double> fp) const override {
    Eigen::Map<Eigen::Vector3d>(fp.data()) = R(t) * kFrame * a_.gp(y_of(t, x), p);
  }

 private:
  Autonomous a_;
  Eigen::Matrix3d Mi_;
};

// y1' = p - c y1^2, y2' = -y2, y3' = -y3: 2 pi-periodic orbits y1 = +-sqrt(p / c), a fold of cycles at p = 0. The
// period map in y1 is y1 -> y1 + 2 pi p - 2 pi c y1^2 + ..., i.e. in x0 = x_p(0) + M y along the unit v = M e1 /
// |M e1| (u = |M e1| y1): u -> u + 2 pi |M e1| p - (2 pi c / |M e1|) u^2, so w_Fp = 2 pi |M e1|, a = -2 pi c / |M e1|,
// p2 = c / |M e1|^2 (p = c y1^2) and |x0 - x0*| = |M e1| sqrt(p / c).
Autonomous fold_of_cycles(double c) {
  return {[c](const Eigen::Vector3d& y, double p) { return Eigen::Vector3d(p - c * y[0] * y[0], -y[1], -y[2]); },
          [c](const Eigen::Vector3d& y, double) {
            return Eigen::Matrix3d(Eigen::Vector3d(-2 * c * y[0], -1, -1).asDiagonal());
          },
          [](const Eigen::Vector3d&, double) { return Eigen::Vector3d(1, 0, 0); }};
}

OrbitOptions four_segments() {
  OrbitOptions oo;
  oo.segments = 4;
  return oo;
}

// The orbit branch of the fold system from y1 = sqrt(0.1 / c) at p = 0.1 (c > 0) through the LPC at p = 0.
Branch fold_branch(const PeriodicOrbitProblem& pr, double c) {
  ContinuationOptions o;
  o.p_min = -0.1;
  o.p_max = 0.1;
  o.max_step = 0.1;
  o.direction = Direction::backward;
  const Eigen::Vector3d x0 = RotatingFrame::xp(0) + kFrame * Eigen::Vector3d(std::sqrt(0.1 / c), 0, 0);
  return continue_branch(pr, pr.shooting_guess(x0, 0.1), 0.1, o);
}

TEST(PeriodMapNormalForm, FoldOfCyclesAgainstTheClosedForm) {
  const double c = 0.7, Me1 = kFrame.col(0).norm();
  const RotatingFrame sys(fold_of_cycles(c));
  const PeriodicOrbitProblem pr(sys, four_segments());
  const Branch b = fold_branch(pr, c);
  const SpecialPoint* lpc = find_special_point(b, SpecialPointType::LPC);
  ASSERT_NE(lpc, nullptr) << b.message;
  EXPECT_NEAR(lpc->p, 0, 1e-8);
  // The engine attaches it (continue_branch's normal_forms).
  ASSERT_TRUE(lpc->normal_form.has_value());
  const NormalForm& nf = *lpc->normal_form;
  EXPECT_EQ(nf.kind, NormalFormKind::fold_of_cycles);
  EXPECT_EQ(nf.criticality, Criticality::not_applicable);
  // Second differences of shootings (accurate to ~1e-11) at h = 1e-3: ~1e-5 rounding, ~1e-6 truncation; measured
  // below 1e-7 relative. Bar 1e-5 relative: a wrong factor 2 or sign is off by 1 (checked below).
  const double a = -kTwoPi * c / Me1, wFp = kTwoPi * Me1, p2 = c / (Me1 * Me1);
  EXPECT_NEAR(nf.coefficient("a"), a, 1e-5 * std::abs(a)) << nf.note;
  EXPECT_NEAR(nf.coefficient("w_Fp"), wFp, 1e-5 * wFp);
  EXPECT_NEAR(nf.coefficient("p2"), p2, 1e-5 * p2);
  EXPECT_NEAR(nf.amplitude, Me1 / std::sqrt(c), 1e-5);
  EXPECT_EQ(nf.exponent, 0.5);
  EXPECT_EQ(nf.side, 1);
  // The check can fail: the opposite sign and half the factor are far outside the bar.
  EXPECT_GT(std::abs(nf.coefficient("a") + a), 1.0);
  EXPECT_GT(std::abs(nf.coefficient("p2") - p2 / 2), 0.1 * p2);
  EXPECT_NE(to_text(nf, "p").find("fold_of_cycles (p2 = "), std::string::npos) << to_text(nf, "p");
  EXPECT_EQ(normal_form_from_json(to_json(nf)).kind, NormalFormKind::fold_of_cycles);
}

TEST(PeriodMapNormalForm, FoldOfCyclesOpeningTheOtherWay) {
  // c < 0: the orbits exist for p < 0; a and p2 change sign, the law's side too.
  const double c = -0.7, Me1 = kFrame.col(0).norm();
  const RotatingFrame sys(fold_of_cycles(c));
  const PeriodicOrbitProblem pr(sys, four_segments());
  const Eigen::Vector3d x0 = RotatingFrame::xp(0);
  const NormalForm nf = fold_of_cycles_normal_form(pr, pr.shooting_guess(x0, 0), 0);
  EXPECT_NEAR(nf.coefficient("a"), -kTwoPi * c / Me1, 1e-5 * kTwoPi);
  EXPECT_NEAR(nf.coefficient("p2"), c / (Me1 * Me1), 1e-5);
  EXPECT_EQ(nf.side, -1);
  // Off the fold (the trajectory from y1 = 0.3 at p = -0.5, which tends to the stable orbit y1 = -0.845): refused.
  const Eigen::Vector3d off_x0 = x0 + kFrame * Eigen::Vector3d(0.3, 0, 0);
  const NormalForm off = fold_of_cycles_normal_form(pr, pr.shooting_guess(off_x0, -0.5), -0.5);
  EXPECT_EQ(off.criticality, Criticality::not_computed);
  EXPECT_NE(off.note.find("J is regular"), std::string::npos) << off.note;
}

// u' = (p + i omega) u + s |u|^2 u (u = u1 + i u2), u3' = -u3, seen in y with u = y + Q(y), Q(y) = (k1 y1^2,
// k2 y1 y2, k3 y2^2): y' = (I + DQ(y))^-1 g(y + Q(y)). At p = 0 the period map in u is
// u -> e^{i theta} u (1 + 2 pi s |u|^2 + ...), theta = 2 pi omega; in the complex coordinate z along the unit
// q0 = (1, -i, 0) / sqrt 2, |u|^2 = 2 |z|^2, so d = 4 pi s; Q has identity linear part (d unchanged) and x0 = M y
// gives d = 4 pi s / |M q0|^2. Invariant circle |u|^2 = -p / s, |mu| = e^{2 pi p}: modulus_p = 2 pi, and its peak in
// x0 is sigma_max(M [e1 e2]) sqrt(p / |s|).
constexpr double kOmega = 0.3, kK1 = 0.4, kK2 = -0.3, kK3 = 0.5;
Eigen::Matrix3d dq(const Eigen::Vector3d& y) {
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero();
  D << 2 * kK1 * y[0], 0, 0, kK2 * y[1], kK2 * y[0], 0, 0, 2 * kK3 * y[1], 0;
  return D;
}
Autonomous neimark_sacker(double s) {
  const auto normal = [s](const Eigen::Vector3d& u, double p) {
    const double a = p + s * (u[0] * u[0] + u[1] * u[1]);
    return Eigen::Vector3d(a * u[0] - kOmega * u[1], kOmega * u[0] + a * u[1], -u[2]);
  };
  const auto u_of = [](const Eigen::Vector3d& y) {
    return Eigen::Vector3d(y[0] + kK1 * y[0] * y[0], y[1] + kK2 * y[0] * y[1], y[2] + kK3 * y[1] * y[1]);
  };
  const auto K = [](const Eigen::Vector3d& y) { return Eigen::Matrix3d(Eigen::Matrix3d::Identity() + dq(y)); };
  Autonomous a;
  a.g = [=](const Eigen::Vector3d& y, double p) { return Eigen::Vector3d(K(y).inverse() * normal(u_of(y), p)); };
  // K F = g(u) differentiated: DQ(dy) F + K dF = Dg(u) K dy, and DQ(dy) F = DQ(F) dy (Q is quadratic).
  a.dg = [=](const Eigen::Vector3d& y, double p) {
    const Eigen::Vector3d u = u_of(y), F = K(y).inverse() * normal(u, p);
    const double r = p + s * (u[0] * u[0] + u[1] * u[1]);
    Eigen::Matrix3d Dg;
    Dg << r + 2 * s * u[0] * u[0], -kOmega + 2 * s * u[0] * u[1], 0, kOmega + 2 * s * u[0] * u[1],
        r + 2 * s * u[1] * u[1], 0, 0, 0, -1;
    return Eigen::Matrix3d(K(y).inverse() * (Dg * K(y) - dq(F)));
  };
  a.gp = [=](const Eigen::Vector3d& y, double) {
    const Eigen::Vector3d u = u_of(y);
    return Eigen::Vector3d(K(y).inverse() * Eigen::Vector3d(u[0], u[1], 0));
  };
  return a;
}

double closed_form_d(double s) {
  const double Mq0 = (kFrame.col(0).squaredNorm() + kFrame.col(1).squaredNorm()) / 2;  // |M q0|^2
  return 4 * kPi * s / Mq0;
}

Branch ns_branch(const PeriodicOrbitProblem& pr) {
  ContinuationOptions o;
  o.p_min = -0.2;
  o.p_max = 0.2;
  o.max_step = 0.1;
  return continue_branch(pr, pr.shooting_guess(RotatingFrame::xp(0), -0.2), -0.2, o);
}

TEST(PeriodMapNormalForm, NeimarkSackerCriticalityAgainstTheClosedForm) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(kFrame.leftCols(2));
  const double peak = svd.singularValues()[0];
  for (const double s : {-1.0, 1.0}) {
    const RotatingFrame sys(neimark_sacker(s));
    const PeriodicOrbitProblem pr(sys, four_segments());
    const Branch b = ns_branch(pr);
    const SpecialPoint* ns = find_special_point(b, SpecialPointType::NS);
    ASSERT_NE(ns, nullptr) << b.message;
    EXPECT_NEAR(ns->p, 0, 1e-8);
    ASSERT_TRUE(ns->normal_form.has_value());
    const NormalForm& nf = *ns->normal_form;
    EXPECT_EQ(nf.kind, NormalFormKind::neimark_sacker);
    EXPECT_EQ(nf.criticality, s < 0 ? Criticality::supercritical : Criticality::subcritical) << nf.note;
    // Measured (s = -1): d off by 4.2e-5 (the third differences' O(h^4) after extrapolation: 9.6e-3, 6.5e-4,
    // 4.2e-5, 3.1e-6 at third = 1e-2 ... 1.25e-3), modulus_p by 1e-11, the amplitude by 2.8e-6. Bars ~5x that.
    const double d = closed_form_d(s);
    EXPECT_NEAR(nf.coefficient("d"), d, 2e-4) << nf.note;
    EXPECT_NEAR(nf.coefficient("theta"), kTwoPi * kOmega, 1e-9);
    EXPECT_NEAR(nf.coefficient("modulus_p"), kTwoPi, 1e-6);
    EXPECT_NEAR(nf.amplitude, peak, 2e-5);
    EXPECT_EQ(nf.side, -s);
    // Fails on a wrong sign, and the quadratic terms are needed: the cubic term alone is off by far more than the bar.
    EXPECT_GT(std::abs(nf.coefficient("d") + d), 1.0);
    EXPECT_GT(std::abs(nf.coefficient("cubic") - d), 0.1) << nf.coefficient("cubic");
    EXPECT_NE(to_text(nf, "p").find(s < 0 ? "neimark_sacker, supercritical (d = " : "neimark_sacker, subcritical"),
              std::string::npos)
        << to_text(nf, "p");
    // The JSON of a branch file carries it and reads it back (the new kind names included).
    const NormalForm back = normal_form_from_json(to_json(nf));
    EXPECT_EQ(back.kind, NormalFormKind::neimark_sacker);
    EXPECT_EQ(back.criticality, nf.criticality);
    EXPECT_EQ(back.coefficient("d"), nf.coefficient("d"));
    EXPECT_EQ(back.amplitude, nf.amplitude);
  }
}

// The NS system made autonomous ((cos t, sin t) -> the oscillator's (c, s)): the orbit x_p (period 2 pi; phase: c is
// extremal at t = 0) with its Poincare map on the section S through x0* = (x_p(0), 1, 0) normal to f(x0*) = (x_p'(0),
// 0, 1). To leading order S meets the invariant torus in the forced circle x_p(0) + M (u, 0) (|u|^2 = -p / s)
// projected along f onto S, i.e. by the orthogonal projection I - n n^T: peak sigma_max((I - n n^T) [M e1, M e2; 0])
// sqrt(p / |s|). Invariants against the forced map's normal form: theta, modulus_p, criticality, side.
TEST(PeriodMapNormalForm, NeimarkSackerOfTheAutonomisedSystem) {
  for (const double s : {-1.0, 1.0}) {
    const RotatingFrame forced(neimark_sacker(s));
    const Autonomised sys(3, [&forced](const Eigen::VectorXd& x, double c, double sn, double p) {
      return Eigen::VectorXd(forced.field(c, sn, Eigen::Vector3d(x[0], x[1], x[2]), p));
    });
    const AutonomousOrbitProblem pr(sys, 3, four_segments());
    const Eigen::VectorXd x0 = Autonomised::state(RotatingFrame::xp(0), 0);
    NormalForm nf;
    if (s < 0) {  // the engine's label on the branch (the subcritical case directly at the closed-form point)
      ContinuationOptions o;
      o.p_min = -0.2;
      o.p_max = 0.2;
      o.max_step = 0.1;
      const Branch b = continue_branch(pr, pr.shooting_guess(x0, kTwoPi, -0.2), -0.2, o);
      const SpecialPoint* ns = find_special_point(b, SpecialPointType::NS);
      ASSERT_NE(ns, nullptr) << b.message;
      EXPECT_NEAR(ns->p, 0, 1e-8);
      ASSERT_TRUE(ns->normal_form.has_value());
      nf = *ns->normal_form;
    } else {
      nf = neimark_sacker_normal_form(pr, pr.shooting_guess(x0, kTwoPi, 0), 0);
    }
    EXPECT_EQ(nf.kind, NormalFormKind::neimark_sacker);
    EXPECT_EQ(nf.criticality, s < 0 ? Criticality::supercritical : Criticality::subcritical) << nf.note;
    EXPECT_EQ(nf.side, -s);
    Eigen::VectorXd n(5);
    n << RotatingFrame::xp_dot_of(1, 0), 0, 1;
    n.normalize();
    Eigen::MatrixXd M2 = Eigen::MatrixXd::Zero(5, 2);
    M2.topRows(3) = kFrame.leftCols(2);
    const Eigen::MatrixXd projected = (Eigen::MatrixXd::Identity(5, 5) - n * n.transpose()) * M2;
    const double peak = Eigen::JacobiSVD<Eigen::MatrixXd>(projected).singularValues()[0];
    // Measured 1.1e-5 relative (d = -15.647173 and 15.647154); bar 1e-4.
    EXPECT_NEAR(nf.amplitude, peak, 1e-4 * peak) << nf.note;
    // The unprojected circle's peak (the forced law's) is far off: the check can fail.
    const double unprojected = Eigen::JacobiSVD<Eigen::MatrixXd>(M2).singularValues()[0];
    EXPECT_GT(std::abs(unprojected - peak), 0.05 * peak);
    // The quadratic terms are needed: 0.317 of d (2 %, a 1 % change of the amplitude, 100x its bar).
    EXPECT_GT(std::abs(nf.coefficient("cubic") - nf.coefficient("d")), 0.01 * std::abs(nf.coefficient("d")));
    const PeriodicOrbitProblem fpr(forced, four_segments());
    const NormalForm f = neimark_sacker_normal_form(fpr, fpr.shooting_guess(RotatingFrame::xp(0), 0), 0);
    EXPECT_NEAR(nf.coefficient("theta"), f.coefficient("theta"), 1e-9);
    EXPECT_NEAR(nf.coefficient("theta"), kTwoPi * kOmega, 1e-9);
    EXPECT_NEAR(nf.coefficient("modulus_p"), f.coefficient("modulus_p"), 1e-6);
    EXPECT_EQ(nf.criticality, f.criticality);
    EXPECT_EQ(nf.side, f.side);
  }
}

// Two step sizes agree, and the default one is within the bar of the closed form (the step convergence of the
// differences: third differences at 2.5e-3 and 1.25e-3, second differences at 1e-3 and 5e-4; each extrapolated from
// its step and half of it).
TEST(PeriodMapNormalForm, StepsConverge) {
  const RotatingFrame sys(neimark_sacker(-1));
  const PeriodicOrbitProblem pr(sys, four_segments());
  const Eigen::VectorXd X = pr.shooting_guess(RotatingFrame::xp(0), 0);
  PeriodMapSteps half;
  half.second = 5e-4;
  half.third = 1.25e-3;
  const NormalForm a = neimark_sacker_normal_form(pr, X, 0), b = neimark_sacker_normal_form(pr, X, 0, half);
  EXPECT_NEAR(a.coefficient("d"), b.coefficient("d"), 2e-4);
  EXPECT_NEAR(a.coefficient("d"), closed_form_d(-1), 2e-4);
  // A coarse third step (1e-2) is off by its O(h^4): 9.6e-3, worse than the default.
  PeriodMapSteps coarse;
  coarse.third = 1e-2;
  const NormalForm c = neimark_sacker_normal_form(pr, X, 0, coarse);
  EXPECT_GT(std::abs(c.coefficient("d") - closed_form_d(-1)), std::abs(a.coefficient("d") - closed_form_d(-1)));
  PeriodMapSteps bad;
  bad.second = 0;
  EXPECT_THROW(neimark_sacker_normal_form(pr, X, 0, bad), InvalidArgument);
  bad.second = 1e-3;
  bad.third = std::nan("");
  try {
    fold_of_cycles_normal_form(pr, X, 0, bad);
    ADD_FAILURE() << "no throw";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("steps.third"), std::string::npos) << e.what();
  }
}

// Another method: the period map of an autonomous flow near a Hopf point is its time-2 pi map, whose NS coefficient
// is d = 2 pi omega l1 (z' = i omega z + c1 z |z|^2: |z| -> |z| (1 + 2 pi Re c1 |z|^2), l1 = Re c1 / omega) in the
// flow's unit eigenvector, i.e. d = 2 pi omega l1 / |M q0|^2 in x0 = M y. l1 comes from hopf_normal_form (the vector
// field's derivatives, Kuznetsov's ODE formula) of g below: quadratic terms, a cubic one and a slaved third
// component, so no closed form is needed.
constexpr double kQ1 = 0.8, kQ2 = -0.6, kQ3 = 0.5, kS = -0.4;
Eigen::Vector3d hopf_g(const Eigen::Vector3d& y, double p) {
  const double r = y[0] * y[0] + y[1] * y[1];
  return {p * y[0] - kOmega * y[1] + kQ1 * y[0] * y[0] + kS * y[0] * r,
          kOmega * y[0] + p * y[1] + kQ2 * y[0] * y[1] + kS * y[1] * r, -y[2] + kQ3 * y[0] * y[0]};
}
Autonomous hopf_flow() {
  Autonomous a;
  a.g = hopf_g;
  a.dg = [](const Eigen::Vector3d& y, double p) {
    Eigen::Matrix3d D;
    D << p + 2 * kQ1 * y[0] + kS * (3 * y[0] * y[0] + y[1] * y[1]), -kOmega + 2 * kS * y[0] * y[1], 0,
        kOmega + kQ2 * y[1] + 2 * kS * y[0] * y[1], p + kQ2 * y[0] + kS * (y[0] * y[0] + 3 * y[1] * y[1]), 0,
        2 * kQ3 * y[0], 0, -1;
    return D;
  };
  a.gp = [](const Eigen::Vector3d& y, double) { return Eigen::Vector3d(y[0], y[1], 0); };
  return a;
}
// g as an equilibrium problem (central-difference Jacobian), for hopf_normal_form.
class FlowOfG final : public ContinuationProblem {
 public:
  Eigen::Index dimension() const override { return 3; }
  void residual(const Eigen::VectorXd& y, double p, Eigen::VectorXd& F) const override {
    F = hopf_g(Eigen::Vector3d(y[0], y[1], y[2]), p);
  }
};

TEST(PeriodMapNormalForm, NeimarkSackerOfATimeMapIsTheFlowsHopfCoefficient) {
  const NormalForm hb = hopf_normal_form(FlowOfG(), Eigen::Vector3d::Zero(), 0, kOmega);
  ASSERT_EQ(hb.criticality, Criticality::supercritical) << hb.note;
  const double Mq0 = (kFrame.col(0).squaredNorm() + kFrame.col(1).squaredNorm()) / 2;
  const double expected = kTwoPi * kOmega * hb.coefficient("l1") / Mq0;
  const RotatingFrame sys(hopf_flow());
  const PeriodicOrbitProblem pr(sys, four_segments());
  const NormalForm ns = neimark_sacker_normal_form(pr, pr.shooting_guess(RotatingFrame::xp(0), 0), 0);
  EXPECT_EQ(ns.criticality, Criticality::supercritical) << ns.note;
  // l1 to ~1e-7, d to ~1e-5 relative (above): bar 1e-4 relative.
  EXPECT_NEAR(ns.coefficient("d"), expected, 1e-4 * std::abs(expected)) << hb.coefficient("l1");
  // The quadratic terms matter here: the cubic term alone is off by more than 10 % (so the check can fail).
  EXPECT_GT(std::abs(ns.coefficient("cubic") - expected), 0.1 * std::abs(expected)) << ns.coefficient("cubic");
}

}  // namespace
}  // namespace rbcstab
