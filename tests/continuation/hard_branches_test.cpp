// Hard branches, each against a reference computed another way and with the status the run
// must end with: a BP pair far closer than any step, a fold on or within rounding of the range end (closed
// forms), and a special point at the range end of a physical branch (the run that located it). The large-S
// out-of-plane branches are branch_jump_test.cpp's (closed form; the grid is slow), the swinging-tumbling
// curve to S = 200 is hard_branches_slow_test.cpp's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "continuation/full_fixtures.hpp"
#include "continuation/modal_fixtures.hpp"
#include "continuation/scene_spec_fixture.hpp"
#include "rbcstab/continuation/branch_file.hpp"
#include "rbcstab/continuation/branch_labels.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/scene_curve.hpp"
#include "rbcstab/continuation/scene_restart.hpp"

namespace rbcstab {
namespace {

using P = ContinuationParameter;

// A closed-form problem with its exact Jacobian (central differences would shift a pitchfork of -x^3 by h^2 ~ 4e-11).
class Fn final : public ContinuationProblem {
 public:
  using Body = std::function<void(const Eigen::VectorXd&, double, Eigen::VectorXd&)>;
  using Jac = std::function<void(const Eigen::VectorXd&, double, Eigen::MatrixXd&)>;
  Fn(Eigen::Index n, Body f, Jac j) : n_(n), f_(std::move(f)), j_(std::move(j)) {}
  Eigen::Index dimension() const override { return n_; }
  void residual(const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) const override {
    F.resize(n_);
    f_(x, p, F);
  }
  void jacobian(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& J) const override {
    J = Eigen::MatrixXd::Zero(n_, n_);
    j_(x, p, J);
  }

 private:
  Eigen::Index n_;
  Body f_;
  Jac j_;
};

std::vector<SpecialPoint> of_type(const Branch& b, SpecialPointType t) {
  std::vector<SpecialPoint> out;
  for (const SpecialPoint& s : b.special_points)
    if (s.type == t) out.push_back(s);
  return out;
}

// Pitchforks at p = 0.3 and 0.3 + gap (x' = (p - 0.3) x - x^3, y' = (p - 0.3 - gap) y - y^3, exact Jacobian), one
// step of 0.5 over both. gap = 1e-6 and 1e-8: two located BPs at their closed-form values (to 1e-11, the bracket),
// in order, 0 -> 1 -> 2 unstable; gap = 1e-12 (below location_tol): two located BPs at one point, 0 -> 1 -> 2
// (engine_test's coincident case). Each ends completed on the bound. Not asserted, a limit (docs/continuation.md):
// at gap = 1e-9 = stability_tol the counts flip 1e-9 past each root, and the run reports three BPs (0 -> 0 at 0.3,
// 0 -> 1 at 0.3 + 1e-9, 1 -> 2 at 0.3 + 2e-9).
TEST(HardBranches, BranchPointPairCloserThanAnyStepIsTwoLocatedPoints) {
  for (const double gap : {1e-6, 1e-8, 1e-12}) {
    const Fn pr(
        2,
        [gap](const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) {
          F[0] = (p - 0.3) * x[0] - x[0] * x[0] * x[0];
          F[1] = (p - 0.3 - gap) * x[1] - x[1] * x[1] * x[1];
        },
        [gap](const Eigen::VectorXd& x, double p, Eigen::MatrixXd& J) {
          J(0, 0) = p - 0.3 - 3 * x[0] * x[0];
          J(1, 1) = p - 0.3 - gap - 3 * x[1] * x[1];
        });
    ContinuationOptions o;
    o.initial_step = o.max_step = 0.5;
    o.p_max = 0.6;
    const Branch b = continue_branch(pr, Eigen::VectorXd::Zero(2), 0.1, o);
    EXPECT_EQ(b.status, ContinuationStatus::completed) << b.message;
    EXPECT_EQ(b.points.back().p, 0.6);
    const std::vector<SpecialPoint> bp = of_type(b, SpecialPointType::BP);
    for (const SpecialPoint& q : b.special_points)
      std::printf("gap %g: %s at p = %.15g (%s, %d -> %d, precision %g)\n", gap, q.name.c_str(), q.p,
                  to_string(q.status).c_str(), q.unstable_before, q.unstable_after, q.precision);
    for (const SpecialPoint& q : bp) EXPECT_EQ(q.status, LocationStatus::located) << gap;
    if (gap > o.location_tol) {
      ASSERT_EQ(bp.size(), 2u) << gap;
      EXPECT_NEAR(bp[0].p, 0.3, 1e-11);  // the bracket (location_tol) with the exact Jacobian
      EXPECT_NEAR(bp[1].p, 0.3 + gap, 1e-11);
      EXPECT_LT(bp[0].p, bp[1].p);
      EXPECT_EQ(bp[0].unstable_after, 1);
      EXPECT_EQ(bp[1].unstable_after, 2);
    } else {
      // Both crossings in one bracket (unresolved by the test functions, whose signs cancel): placed where the
      // unstable count flips, that is where the eigenvalues pass stability_tol (1e-9 past the root:
      // |d lambda/dp| = 1), one BP per real eigenvalue that crossed, 0 -> 1 -> 2 (before: one BP carrying 0 -> 2).
      ASSERT_EQ(bp.size(), 2u) << gap;
      for (const SpecialPoint& q : bp) EXPECT_NEAR(q.p, 0.3 + o.stability_tol, 1e-11);
      EXPECT_EQ(bp[0].p, bp[1].p);
      EXPECT_EQ(bp[0].unstable_before, 0);
      EXPECT_EQ(bp[0].unstable_after, 1);
      EXPECT_EQ(bp[1].unstable_before, 1);
      EXPECT_EQ(bp[1].unstable_after, 2);
    }
  }
}

// The fold p = x^2 (F = p - x^2, fold at p = 0, x = 0) continued from p = 1 (x = 1) towards p_min = the fold's value
// and within rounding of it: with p_min <= 0 the run passes the fold, locates it (closed form: p = 0, x = 0 to the
// bracket, 1e-11 in x hence 1e-22 in p) and ends completed on p_max on the other half; with p_min = +1e-14 the
// fold lies outside the range (1e-7 in x from the end, far beyond location_tol): the run ends completed on the
// bound, x = 1e-7, with no LP.
TEST(HardBranches, FoldAtOrWithinRoundingOfTheRangeEnd) {
  const Fn pr(
      1, [](const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) { F[0] = p - x[0] * x[0]; },
      [](const Eigen::VectorXd& x, double, Eigen::MatrixXd& J) { J(0, 0) = -2 * x[0]; });
  for (const double p_min : {0.0, -1e-14, 1e-14}) {
    ContinuationOptions o;
    o.p_min = p_min;
    o.p_max = 1;
    o.max_step = 0.3;
    o.direction = Direction::backward;
    const Branch b = continue_branch(pr, Eigen::VectorXd::Ones(1), 1.0, o);
    EXPECT_EQ(b.status, ContinuationStatus::completed) << p_min << ": " << b.message;
    const std::vector<SpecialPoint> lp = of_type(b, SpecialPointType::LP);
    if (p_min <= 0) {
      ASSERT_EQ(lp.size(), 1u) << p_min;
      EXPECT_EQ(lp[0].status, LocationStatus::located);
      EXPECT_NEAR(lp[0].x[0], 0.0, 1e-11);
      EXPECT_EQ(lp[0].p, p_min);
      EXPECT_EQ(b.points.back().p, p_min);
      EXPECT_NEAR(b.points.back().x[0], 0.0, 1e-11);
    } else {
      EXPECT_TRUE(lp.empty()) << lp.size() << " LP at p = " << lp[0].p << ", x = " << lp[0].x[0];
      EXPECT_EQ(b.points.back().p, p_min);
      EXPECT_NEAR(b.points.back().x[0], 1e-7, 1e-12);
    }
    std::printf("fold, p_min = %g: %zu points, %zu LP, %zu rejected steps, ended %s\n", p_min, b.points.size(),
                lp.size(), b.counters.rejected_steps, b.message.c_str());
  }
}

// The full model's l = 4 crossing (ForcedRun of full_equilibrium_test.cpp: a BP (0 -> 1) and four HBs (to 9) at the
// same C, against the nested closed form there) is a range end when a branch is continued to its value.
// From above (the start, C = 0.08, down to it) the unstable count flips at the end and both are reported there
// (as before). From below (the last label, C = 0.012, up to it) the count stays 9 at the end: the HB product's
// secant has its zero within location_tol beyond the end, so the HB is reported there, located (before: no
// special point at all), and so is the BP now: the first run places the HBs at the BP's zero of the determinant
// (before: where the count flipped, 2e-12 in C short of it, and the BP's zero lay beyond location_tol). The HB carries
// its pair's frequency (omega = 1/2 .. 2, not 0: the HB curve starts from it). Reference: the run that located the
// crossing.
TEST(HardBranches, FullModelCrossingAtTheRangeEndIsReportedThere) {
  BranchSpec spec = test::spec_of(full_fixtures::forced_scene(0.08, 5, 1e-3), ProblemKind::full, P::C, 0.012, 0.08,
                                  Direction::backward);
  spec.engine.max_step = 0.05;
  const SceneBranch first = continue_scene(spec);
  const SpecialPoint* hb = find_special_point(first.branch.branch, SpecialPointType::HB);
  ASSERT_NE(hb, nullptr);
  EXPECT_GT(std::abs(hb->eigenvalue.imag()), 0.4);  // the unresolved HB names its pair
  const ContinuationRun run = parse_branch_file(branch_file_json(first).dump(1), "t.json");
  for (const bool from_above : {true, false}) {
    RestartChanges ch;
    (from_above ? ch.p_min : ch.p_max) = hb->p;
    ch.direction = from_above ? Direction::backward : Direction::forward;
    const std::vector<int>& labels = first.branch.point_labels;
    const SceneBranch to = restart(run, from_above ? labels.front() : labels.back(), ch);
    const Branch& b = to.branch.branch;
    ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
    EXPECT_EQ(b.points.back().p, hb->p);
    const SpecialPoint* q = find_special_point(b, SpecialPointType::HB);
    ASSERT_NE(q, nullptr) << from_above;
    EXPECT_EQ(q->p, hb->p);
    EXPECT_EQ(q->status, LocationStatus::located);
    EXPECT_GT(std::abs(q->eigenvalue.imag()), 0.4);
    const SpecialPoint* bp = find_special_point(b, SpecialPointType::BP);
    ASSERT_NE(bp, nullptr) << from_above;  // from below: none before the coincident crossings were merged
    EXPECT_EQ(bp->p, hb->p);
    EXPECT_EQ(bp->status, LocationStatus::located);
  }
  // ... and the HB curve starts from the restarted branch's HB as from the first run's.
  const auto k = static_cast<std::size_t>(hb - first.branch.branch.special_points.data());
  const SceneCurve c =
      restart_curve(run, first.branch.special_labels.at(k), test::curve_of(CurveKind::HB, P::B, 0.9, 1.1));
  EXPECT_TRUE(c.started) << c.message;
}

}  // namespace
}  // namespace rbcstab

namespace rbcstab {
namespace {

// The post-instability branch's own BP at alpha = 60 (sigma_3^c = sigma_4^c, C = B/60 exactly): the states with
// both a_3 and a_4 exist only there, so the branch switched onto is vertical (closed form: C = 1/60 at every
// point, B = 1). The start (residual at rounding, Jacobian singular) is kept, the run ends completed at
// max_points, every point at C = 1/60 to 1e-12, and the tangent's p component (rounding noise, measured 1e-16)
// is not read as folds: no LP (before, an LP every few points).
TEST(HardBranches, SwitchOntoAVerticalSetHasNoFolds) {
  BranchSpec spec = test::spec_of(modal_fixtures::scene(0.04, 6), ProblemKind::modal, P::C, 0.01, 0.1, Direction::both);
  const ContinuationRun onset = parse_branch_file(branch_file_json(continue_scene(spec)).dump(1), "t.json");
  const SceneBranch post = switch_at_label(onset, resolve_label(onset, "BP:l=3", "switch_at"));
  ASSERT_TRUE(post.switched && post.switched->switched);
  const ContinuationRun run = parse_branch_file(branch_file_json(post).dump(1), "t.json");
  int bp4 = 0;
  for (const LabelledPoint& lp : labelled_points(run))
    if (lp.branch == 2 && lp.type == "BP" && bp4 == 0) bp4 = lp.label;
  ASSERT_GT(bp4, 0);
  RestartChanges ch;
  ch.max_points = 40;
  const SceneBranch v = switch_at_label(run, bp4, ch);
  ASSERT_TRUE(v.switched.has_value());
  ASSERT_TRUE(v.switched->switched) << v.switched->message;
  const Branch& b = v.switched->branch.branch;
  EXPECT_EQ(b.status, ContinuationStatus::completed) << b.message;
  EXPECT_GE(b.points.size(), 20u);
  for (const BranchPoint& q : b.points) EXPECT_NEAR(q.p, 1.0 / 60, 1e-12);
  EXPECT_TRUE(of_type(b, SpecialPointType::LP).empty()) << of_type(b, SpecialPointType::LP).size();
}

}  // namespace
}  // namespace rbcstab

namespace rbcstab {
namespace {

// Whether the special points of b at the full model's l-crossing near C (Upsilon_l = 0: the real m = 0 eigenvalue
// and the pairs Upsilon_l +- i m/2, m = 1..l, cross together) say what crossed: one BP, mode l m = 0, carrying
// one unstable mode, and one HB per pair, mode l and its m, omega = m/2, carrying two, all at the BP's value,
// located, the count chained through them. "" when they do, else what is wrong.
std::string crossing_defect(const Branch& b, int l, double C) {
  std::vector<const SpecialPoint*> at;
  for (const SpecialPoint& q : b.special_points)
    if (std::abs(q.p - C) < 1e-6) at.push_back(&q);
  std::ostringstream os;
  const SpecialPoint* bp = nullptr;
  std::vector<int> ms;
  for (const SpecialPoint* q : at) {
    if (q->type == SpecialPointType::BP) {
      if (bp) os << "two BPs; ";
      bp = q;
    } else if (q->type == SpecialPointType::HB) {
      ms.push_back(q->mode_m.value_or(-1));
      if (std::abs(q->unstable_after - q->unstable_before) != 2)
        os << "HB carries " << q->unstable_before << " -> " << q->unstable_after << "; ";
      if (q->mode_l != l || std::abs(q->eigenvalue.imag() - 0.5 * q->mode_m.value_or(-1)) > 1e-6)
        os << "HB omega " << q->eigenvalue.imag() << " mode l " << q->mode_l.value_or(-1) << " m " << ms.back() << "; ";
    }
  }
  if (!bp) return os.str() + "no BP";
  if (bp->mode_l != l || bp->mode_m != 0) os << "BP mode not l = " << l << " m = 0; ";
  if (std::abs(bp->unstable_after - bp->unstable_before) != 1)
    os << "BP carries " << bp->unstable_before << " -> " << bp->unstable_after << "; ";
  std::sort(ms.begin(), ms.end());
  std::vector<int> want;
  for (int m = 1; m <= l; ++m) want.push_back(m);
  if (ms != want) os << ms.size() << " HBs, not one per m = 1.." << l << "; ";
  for (std::size_t k = 0; k < at.size(); ++k) {
    if (at[k]->p != bp->p || at[k]->status != LocationStatus::located) os << "point " << k << " off the BP; ";
    if (k > 0 && at[k]->unstable_before != at[k - 1]->unstable_after) os << "count not chained at " << k << "; ";
  }
  return os.str();
}

// The unforced full model (L = 4, the modal scene): its ellipsoidal branch in C over [0.02, 0.08] crosses
// l = 3 and l = 4 (Upsilon_l(sigma) = 0), each a real eigenvalue and l pairs at once. Continued down (stable
// first) and up (from the unstable end), each crossing is one BP (l, m = 0, one mode) and l HBs (their m),
// at the value where the modal level (another model level: one real eigenvalue per l) locates its BP (1e-9:
// both brackets are 1e-11 in (x, p)). Before, the crossing was a BP carrying no change (0 -> 0) and one HB
// carrying 1 + 2l with no mode; crossing_defect reports that output (the check can fail).
TEST(HardBranches, FullModelOnsetIsABranchPointWithItsHopfPairs) {
  for (const Direction d : {Direction::backward, Direction::forward}) {
    const double C0 = d == Direction::backward ? 0.08 : 0.02;
    BranchSpec spec = test::spec_of(modal_fixtures::scene(C0, 4), ProblemKind::full, P::C, 0.02, 0.08, d);
    const Branch full = continue_scene(spec).branch.branch;
    spec.kind = ProblemKind::modal;
    const Branch modal = continue_scene(spec).branch.branch;
    ASSERT_EQ(full.status, ContinuationStatus::completed) << full.message;
    const std::vector<SpecialPoint> modal_bp = of_type(modal, SpecialPointType::BP);
    ASSERT_EQ(modal_bp.size(), 2u);
    for (const SpecialPoint& m : modal_bp) {
      ASSERT_TRUE(m.mode_l.has_value());
      EXPECT_EQ(crossing_defect(full, *m.mode_l, m.p), "") << "l = " << *m.mode_l << ", C = " << m.p;
      const SpecialPoint* bp = nullptr;
      for (const SpecialPoint& q : full.special_points)
        if (q.type == SpecialPointType::BP && q.mode_l == m.mode_l) bp = &q;
      ASSERT_NE(bp, nullptr);
      EXPECT_NEAR(bp->p, m.p, 1e-9);
    }
    EXPECT_EQ(full.special_points.size(), 2u + 3u + 4u);
  }
  // The old output at the l = 4 crossing (FullEquilibrium's forced run, measured before the fix): BP 0 -> 0 with
  // its mode, one HB 0 -> 9 without one, 2e-12 apart.
  Branch old;
  SpecialPoint bp, hb;
  bp.type = SpecialPointType::BP, bp.p = 0.0152723447521286, bp.status = LocationStatus::located;
  bp.mode_l = 4, bp.mode_m = 0;
  hb.type = SpecialPointType::HB, hb.p = 0.0152723447499965, hb.status = LocationStatus::located;
  hb.unstable_after = 9, hb.eigenvalue = {1.15e-9, 0.5};
  old.special_points = {bp, hb};
  const std::string defect = crossing_defect(old, 4, bp.p);
  EXPECT_NE(defect.find("BP carries 0 -> 0"), std::string::npos) << defect;
  EXPECT_NE(defect.find("HB carries 0 -> 9"), std::string::npos) << defect;
  EXPECT_NE(defect.find("1 HBs, not one per m"), std::string::npos) << defect;
}

}  // namespace
}  // namespace rbcstab
