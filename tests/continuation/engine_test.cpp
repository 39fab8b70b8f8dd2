// The pseudo-arclength engine on textbook normal forms whose branches and bifurcation points are
// known in closed form (Kuznetsov, Elements of Applied Bifurcation Theory, ch. 3).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {

// A problem from a lambda; the Jacobian is left to the engine's finite differences unless given.
class Lambda final : public ContinuationProblem {
 public:
  using Fn = std::function<void(const Eigen::VectorXd&, double, Eigen::VectorXd&)>;
  using Jn = std::function<void(const Eigen::VectorXd&, double, Eigen::MatrixXd&)>;
  Lambda(Eigen::Index n, Fn f, Jn j = {}) : n_(n), f_(std::move(f)), j_(std::move(j)) {}
  Eigen::Index dimension() const override { return n_; }
  void residual(const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) const override {
    F.resize(n_);
    f_(x, p, F);
  }
  void jacobian(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& J) const override {
    if (j_) {
      J.resize(n_, n_);
      j_(x, p, J);
    } else {
      ContinuationProblem::jacobian(x, p, J);
    }
  }

 private:
  Eigen::Index n_;
  Fn f_;
  Jn j_;
};

Eigen::VectorXd vec(std::initializer_list<double> v) {
  Eigen::VectorXd x(static_cast<Eigen::Index>(v.size()));
  Eigen::Index i = 0;
  for (double d : v) x[i++] = d;
  return x;
}

std::vector<SpecialPoint> of_type(const Branch& b, SpecialPointType t) {
  std::vector<SpecialPoint> out;
  for (const auto& s : b.special_points)
    if (s.type == t) out.push_back(s);
  return out;
}

// Located to 1e-8 is the required accuracy; location_tol = 1e-11 (bracket width in (x, p)) leaves margin
// for the O(|x|^2) relation between p and the arclength at a fold.
constexpr double kLocated = 1e-8;

Lambda fold_problem(bool analytic) {
  return Lambda(
      1, [](const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) { F[0] = p - x[0] * x[0]; },
      analytic ? Lambda::Jn([](const Eigen::VectorXd& x, double, Eigen::MatrixXd& J) { J(0, 0) = -2 * x[0]; })
               : Lambda::Jn{});
}

TEST(ContinuationEngine, FoldIsPassedAndLocatedFromBothSides) {
  for (bool analytic : {true, false}) {
    const Lambda pr = fold_problem(analytic);
    ContinuationOptions o;
    o.p_max = 1.0;
    o.max_step = 0.1;
    o.direction = Direction::backward;  // p decreasing from the stable upper branch x = sqrt(p)
    const Branch b = continue_branch(pr, vec({1.0}), 1.0, o);
    ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
    // Around the fold, down the unstable lower branch and back to the bound p = 1 at x = -1 exactly.
    EXPECT_DOUBLE_EQ(b.points.back().p, 1.0);
    EXPECT_NEAR(b.points.back().x[0], -1.0, 1e-12);
    for (const auto& pt : b.points) {
      EXPECT_NEAR(pt.x[0] * pt.x[0], pt.p, 1e-12);  // on the branch p = x^2
      EXPECT_EQ(pt.stable, pt.x[0] > 0) << "x = " << pt.x[0];
    }
    const auto lp = of_type(b, SpecialPointType::LP);
    ASSERT_EQ(lp.size(), 1u);
    EXPECT_EQ(lp[0].status, LocationStatus::located);
    EXPECT_LT(std::abs(lp[0].p), kLocated);
    EXPECT_LT(std::abs(lp[0].x[0]), kLocated);
    EXPECT_EQ(lp[0].unstable_before, 0);
    EXPECT_EQ(lp[0].unstable_after, 1);
    EXPECT_TRUE(of_type(b, SpecialPointType::BP).empty());
    EXPECT_TRUE(of_type(b, SpecialPointType::HB).empty());

    // The other way round: start on the unstable branch, continue forward in p after turning.
    o.direction = Direction::both;
    const Branch c = continue_branch(pr, vec({-0.5}), 0.25, o);
    ASSERT_EQ(c.special_points.size(), 1u);
    EXPECT_EQ(c.special_points[0].type, SpecialPointType::LP);
    EXPECT_LT(std::abs(c.special_points[0].p), kLocated);
    EXPECT_DOUBLE_EQ(c.points.front().p, 1.0);
    EXPECT_DOUBLE_EQ(c.points.back().p, 1.0);
    // Ordered along the branch: from x = +1 (backward part, reversed) to x = -1.
    EXPECT_NEAR(c.points.front().x[0], 1.0, 1e-12);
    EXPECT_NEAR(c.points.back().x[0], -1.0, 1e-12);
    EXPECT_EQ(c.special_points[0].unstable_before, 0);
    EXPECT_EQ(c.special_points[0].unstable_after, 1);
  }
}

TEST(ContinuationEngine, TranscriticalAndPitchforkBranchPoints) {
  // x' = (p - 0.3) x - x^2 and x' = (p - 0.3) x - x^3: BP at p = 0.3 on x = 0 (off the start grid).
  for (int kind : {0, 1}) {
    const Lambda pr(1, [kind](const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) {
      F[0] = (p - 0.3) * x[0] - (kind == 0 ? x[0] * x[0] : x[0] * x[0] * x[0]);
    });
    ContinuationOptions o;
    o.p_min = -1;
    o.p_max = 1;
    o.max_step = 0.07;
    const Branch b = continue_branch(pr, vec({0.0}), -1.0, o);
    ASSERT_EQ(b.status, ContinuationStatus::completed) << b.message;
    const auto bp = of_type(b, SpecialPointType::BP);
    ASSERT_EQ(bp.size(), 1u) << "kind " << kind;
    EXPECT_EQ(bp[0].status, LocationStatus::located);
    EXPECT_NEAR(bp[0].p, 0.3, kLocated);
    EXPECT_LT(bp[0].precision, kLocated);
    EXPECT_EQ(bp[0].unstable_before, 0);
    EXPECT_EQ(bp[0].unstable_after, 1);
    EXPECT_TRUE(of_type(b, SpecialPointType::LP).empty());
    for (const auto& pt : b.points) EXPECT_NEAR(pt.x[0], 0.0, 1e-12);  // stays on the trivial branch
  }
}

// Hopf normal form in Cartesian form, HB at p = p_h with eigenvalues (p - p_h) +- i omega.
void hopf(const Eigen::VectorXd& x, double mu, double omega, double* F, Eigen::Index i) {
  const double r2 = x[i] * x[i] + x[i + 1] * x[i + 1];
  F[i] = mu * x[i] - omega * x[i + 1] - x[i] * r2;
  F[i + 1] = omega * x[i] + mu * x[i + 1] - x[i + 1] * r2;
}

TEST(ContinuationEngine, HopfLocatedWithFrequency) {
  const double p_h = 0.123456789;
  // Add a decoupled stable direction so the product test sees real-complex pairs too.
  const Lambda pr(3, [p_h](const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) {
    hopf(x, p - p_h, 2.0, F.data(), 0);
    F[2] = -x[2] + x[0] * x[0];
  });
  ContinuationOptions o;
  o.p_max = 1;
  const Branch b = continue_branch(pr, vec({0, 0, 0}), -0.5, o);
  const auto hb = of_type(b, SpecialPointType::HB);
  ASSERT_EQ(hb.size(), 1u);
  EXPECT_EQ(hb[0].status, LocationStatus::located);
  EXPECT_NEAR(hb[0].p, p_h, kLocated);
  EXPECT_NEAR(hb[0].eigenvalue.imag(), 2.0, 1e-8);
  EXPECT_EQ(hb[0].unstable_before, 0);
  EXPECT_EQ(hb[0].unstable_after, 2);
  EXPECT_TRUE(of_type(b, SpecialPointType::BP).empty());
  EXPECT_TRUE(of_type(b, SpecialPointType::LP).empty());
}

TEST(ContinuationEngine, TwoHopfPairsCrossingInOneStepAreBothFound) {
  // Pairs cross at p = 0.3 and 0.3005: one step of 0.5 spans both, so the product test does not
  // change sign over the step; the jump of the unstable count by 4 makes the engine split it.
  const Lambda pr(4, [](const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) {
    hopf(x, p - 0.3, 1.0, F.data(), 0);
    hopf(x, p - 0.3005, 3.0, F.data(), 2);
  });
  ContinuationOptions o;
  o.initial_step = 0.5;
  o.max_step = 0.5;
  o.p_max = 0.6;
  const Branch b = continue_branch(pr, vec({0, 0, 0, 0}), 0.1, o);
  const auto hb = of_type(b, SpecialPointType::HB);
  ASSERT_EQ(hb.size(), 2u);
  EXPECT_NEAR(hb[0].p, 0.3, kLocated);
  EXPECT_NEAR(hb[1].p, 0.3005, kLocated);
  EXPECT_NEAR(std::abs(hb[0].eigenvalue.imag()), 1.0, 1e-8);
  EXPECT_NEAR(std::abs(hb[1].eigenvalue.imag()), 3.0, 1e-8);
  EXPECT_EQ(b.points.back().n_unstable, 4);
}

TEST(ContinuationEngine, TwoRealCrossingsInOneStepAreBothFound) {
  // Pitchforks at p = 0.3 and 0.3005 on the trivial branch; one step of 0.5 spans both. The BP
  // determinant (p - 0.3)(p - 0.3005) keeps its sign over the step, and the HB product's zero (the
  // pair sum at p = 0.30025) is a neutral saddle, rejected: only the unstable count (0 -> 2) shows
  // the two crossings, and the engine must split the step until each one is located.
  const Lambda pr(2, [](const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) {
    F[0] = (p - 0.3) * x[0] - x[0] * x[0] * x[0];
    F[1] = (p - 0.3005) * x[1] - x[1] * x[1] * x[1];
  });
  ContinuationOptions o;
  o.initial_step = 0.5;
  o.max_step = 0.5;
  o.p_max = 0.6;
  const Branch b = continue_branch(pr, vec({0, 0}), 0.1, o);
  EXPECT_TRUE(of_type(b, SpecialPointType::HB).empty());
  const auto bp = of_type(b, SpecialPointType::BP);
  ASSERT_EQ(bp.size(), 2u);
  EXPECT_NEAR(bp[0].p, 0.3, kLocated);
  EXPECT_NEAR(bp[1].p, 0.3005, kLocated);
  for (const auto& q : bp) EXPECT_EQ(q.status, LocationStatus::located);
  EXPECT_EQ(b.points.back().n_unstable, 2);
}

TEST(ContinuationEngine, CoincidentRealCrossingsAreOneBranchPointEachAtOnePoint) {
  // x' = px - x^3, y' = py - y^3: two real eigenvalues cross together at p = 0 (a BP of multiplicity
  // two). No test function changes sign; splitting cannot separate them: the bracket shrinks below
  // location_tol and the engine reports one BP per real eigenvalue that crossed (from the spectrum: real, not
  // HB) at that one point, the count chained 0 -> 1 -> 2 (before: one BP carrying 0 -> 2).
  const Lambda pr(2, [](const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) {
    F[0] = p * x[0] - x[0] * x[0] * x[0];
    F[1] = p * x[1] - x[1] * x[1] * x[1];
  });
  ContinuationOptions o;
  o.initial_step = 0.3;
  o.max_step = 0.3;
  o.p_max = 0.5;
  const Branch b = continue_branch(pr, vec({0, 0}), -0.5, o);
  EXPECT_TRUE(of_type(b, SpecialPointType::HB).empty());
  const auto bp = of_type(b, SpecialPointType::BP);
  ASSERT_EQ(bp.size(), 2u);
  for (const auto& q : bp) {
    EXPECT_NEAR(q.p, 0.0, kLocated);
    EXPECT_EQ(q.p, bp[0].p);
    EXPECT_EQ(q.status, LocationStatus::located);
    EXPECT_LE(q.precision, o.location_tol);
  }
  EXPECT_EQ(bp[0].unstable_before, 0);
  EXPECT_EQ(bp[0].unstable_after, 1);
  EXPECT_EQ(bp[1].unstable_before, 1);
  EXPECT_EQ(bp[1].unstable_after, 2);
}

TEST(ContinuationEngine, NeutralSaddleIsNotReportedAsHopf) {
  // Real eigenvalues l1 = p - 0.2 and l2 = -0.1: the pair sum l1 + l2 vanishes at p = 0.3, a neutral
  // saddle (no imaginary part), which the HB test function sees but the engine must reject.
  const Lambda pr(2, [](const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) {
    F[0] = (p - 0.2) * x[0];
    F[1] = -0.1 * x[1];
  });
  ContinuationOptions o;
  o.p_max = 0.6;
  o.max_step = 0.05;
  const Branch b = continue_branch(pr, vec({0, 0}), 0.0, o);
  EXPECT_TRUE(of_type(b, SpecialPointType::HB).empty());
  const auto bp = of_type(b, SpecialPointType::BP);  // the real crossing at p = 0.2 is a BP (x = 0 and any x0)
  ASSERT_EQ(bp.size(), 1u);
  EXPECT_NEAR(bp[0].p, 0.2, kLocated);
}

TEST(ContinuationEngine, UserEventAndStop) {
  const Lambda pr = fold_problem(true);
  ContinuationOptions o;
  o.direction = Direction::backward;
  o.events.push_back({"x_half", [](const Eigen::VectorXd& x, double) { return x[0] - 0.5; }});
  o.stop = [](const Eigen::VectorXd& x, double) { return x[0] < -0.2; };
  const Branch b = continue_branch(pr, vec({1.0}), 1.0, o);
  ASSERT_EQ(b.status, ContinuationStatus::completed);
  EXPECT_EQ(b.message, "user stop");
  EXPECT_LT(b.points.back().x[0], -0.2);
  const auto uz = of_type(b, SpecialPointType::UZ);
  ASSERT_EQ(uz.size(), 1u);
  EXPECT_EQ(uz[0].name, "x_half");
  EXPECT_NEAR(uz[0].x[0], 0.5, 1e-11);
  EXPECT_NEAR(uz[0].p, 0.25, 1e-11);
}

TEST(ContinuationEngine, DomainErrorsAndBadOptions) {
  // F = p - x^2 with p < 0.5 refused: the branch ends with outside_domain and the message.
  const Lambda pr(1, [](const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) {
    require(p >= 0.5, "p", p, ">= 0.5");
    F[0] = p - x[0] * x[0];
  });
  ContinuationOptions o;
  o.direction = Direction::backward;
  const Branch b = continue_branch(pr, vec({1.0}), 1.0, o);
  EXPECT_EQ(b.status, ContinuationStatus::outside_domain);
  EXPECT_NE(b.message.find("p ="), std::string::npos);
  EXPECT_GE(b.points.back().p, 0.5);
  EXPECT_LT(b.points.back().p, 0.5 + 1e-3);  // approaches the edge until the step falls below min_step

  ContinuationOptions bad;
  bad.initial_step = -1;
  try {
    bad.validate();
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "initial_step");
  }
  EXPECT_THROW(continue_branch(pr, vec({1.0}), 2.0,
                               [] {
                                 ContinuationOptions q;
                                 q.p_max = 1.5;
                                 return q;
                               }()),
               InvalidArgument);
  // A rough start (x = 1 at p = 4, root x = 2) is corrected by Newton before continuing.
  const Branch s = continue_branch(pr, vec({1.0}), 4.0, [] {
    ContinuationOptions q;
    q.max_points = 5;
    return q;
  }());
  EXPECT_EQ(s.status, ContinuationStatus::completed);
  EXPECT_NEAR(s.points.front().x[0], 2.0, 1e-14);
}

TEST(Engine, FindSpecialPointCountsByTypeInBranchOrder) {
  Branch b;
  for (SpecialPointType t : {SpecialPointType::BP, SpecialPointType::LP, SpecialPointType::BP}) {
    SpecialPoint sp;
    sp.type = t;
    sp.p = static_cast<double>(b.special_points.size());
    b.special_points.push_back(sp);
  }
  ASSERT_NE(find_special_point(b, SpecialPointType::BP), nullptr);
  EXPECT_EQ(find_special_point(b, SpecialPointType::BP)->p, 0);
  EXPECT_EQ(find_special_point(b, SpecialPointType::BP, 2)->p, 2);
  EXPECT_EQ(find_special_point(b, SpecialPointType::LP)->p, 1);
  EXPECT_EQ(find_special_point(b, SpecialPointType::BP, 3), nullptr);
  EXPECT_EQ(find_special_point(b, SpecialPointType::HB), nullptr);
}

}  // namespace
}  // namespace rbcstab
