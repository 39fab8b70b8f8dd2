// The continuation tracer of envelope zero sets (sweep/zero_set.hpp) on closed-form criteria.
#include <gtest/gtest.h>

#include <cmath>

#include "rbcstab/core/error.hpp"
#include "rbcstab/sweep/zero_set.hpp"

namespace rbcstab {
namespace {

// Two "modes" whose growth regions are the unit disks centred at (0, 0) and (a, 0): g_3 = 1 - x^2 - y^2,
// g_4 = 1 - (x - a)^2 - y^2. The envelope's zero set is the outline of the union of the disks: a closed
// curve that does not touch the rectangle's edges, with two corners where the circles meet,
// (a/2, +-sqrt(1 - a^2/4)), and turning points of x at x = -1 (mode 3) and x = 1 + a (mode 4).
ModeCriteria two_disks(double a) {
  ModeCriteria c;
  c.l_min = 3;
  c.description = "two disks";
  c.at = [a](double x, double y) {
    CriterionSample s;
    s.g = {1 - x * x - y * y, 1 - (x - a) * (x - a) - y * y};
    return s;
  };
  return c;
}

// Every point lies on its mode's circle (the engine's corrector converges to |g| ~ 1e-16; polishing
// guarantees residual_tol = 1e-12, so 1e-12 on g); corners match the closed form to 1e-9 (the engine
// locates events to a bracket of 1e-11 in the unit square, times the box size 5); the curve closes and
// passes both turning points in x.
TEST(ZeroSet, UnionOfDisksClosedCurveCornersAndTurningPoints) {
  const double a = 1.0;
  const PlaneBox box{-2, 3, -2, 2};
  const ZeroSetResult r = trace_zero_set(two_disks(a), box);
  ASSERT_EQ(r.chains, 1u) << (r.notes.empty() ? "" : r.notes.front());
  EXPECT_TRUE(r.notes.empty());
  ASSERT_EQ(r.corners.size(), 2u);
  EXPECT_GE(r.turning_points, 2u);
  double xmin = 1e300, xmax = -1e300;
  std::size_t n = 0;
  for (const ZeroSetPiece& p : r.pieces)
    for (const ZeroSetPoint& q : p.points) {
      const double g = p.l == 3 ? 1 - q.x * q.x - q.y * q.y : 1 - (q.x - a) * (q.x - a) - q.y * q.y;
      EXPECT_LE(std::abs(g), 1e-12) << "mode " << p.l << " at " << q.x << ", " << q.y;
      EXPECT_EQ(q.g, g);
      // The envelope: the other disk's criterion is not larger (up to the corner's location precision).
      const double other = p.l == 3 ? 1 - (q.x - a) * (q.x - a) - q.y * q.y : 1 - q.x * q.x - q.y * q.y;
      EXPECT_LE(other, 1e-9);
      xmin = std::min(xmin, q.x);
      xmax = std::max(xmax, q.x);
      ++n;
    }
  EXPECT_GT(n, 50u);
  // The turning points are on the curve: the extremes of x are -1 and 1 + a to within the chord sagitta
  // (step <= 0.02 of the box: (0.1)^2 / 8 on a unit circle ~ 1.3e-3).
  EXPECT_NEAR(xmin, -1, 2e-3);
  EXPECT_NEAR(xmax, 1 + a, 2e-3);
  const double yc = std::sqrt(1 - a * a / 4);
  for (const ZeroSetCorner& k : r.corners) {
    EXPECT_NEAR(k.x, a / 2, 1e-9);
    EXPECT_NEAR(std::abs(k.y), yc, 1e-9);
    EXPECT_NE(k.l_from, k.l_to);
    EXPECT_EQ(k.status, LocationStatus::located);
  }
  // Closed: the chain's last point is its first.
  const ZeroSetPoint& first = r.pieces.front().points.front();
  const ZeroSetPoint& last = r.pieces.back().points.back();
  EXPECT_NEAR(first.x, last.x, 1e-12);
  EXPECT_NEAR(first.y, last.y, 1e-12);
  std::cout << "two disks: " << r.pieces.size() << " pieces, " << n << " points, " << r.evaluations << " evaluations, "
            << r.turning_points << " turning points\n";
}

// A curve entering and leaving through the edges (the disks cut by the box): started on an edge, ends
// exactly on an edge, oriented towards increasing x.
TEST(ZeroSet, CurveCutByTheBoxStartsAndEndsOnEdges) {
  const PlaneBox box{-0.5, 3, -2, 0.5};  // cuts both disks (a = 1)
  const ZeroSetResult r = trace_zero_set(two_disks(1.0), box);
  ASSERT_EQ(r.chains, 1u) << (r.notes.empty() ? "" : r.notes.front());
  ASSERT_EQ(r.corners.size(), 1u);  // only the lower corner (0.5, -0.866) is inside
  EXPECT_NEAR(r.corners[0].x, 0.5, 1e-9);
  EXPECT_NEAR(r.corners[0].y, -std::sqrt(0.75), 1e-9);
  EXPECT_EQ(r.corners[0].l_from, 3);
  EXPECT_EQ(r.corners[0].l_to, 4);
  const ZeroSetPoint& first = r.pieces.front().points.front();
  const ZeroSetPoint& last = r.pieces.back().points.back();
  EXPECT_NEAR(first.x, -0.5, 1e-12);  // the circle x^2 + y^2 = 1 leaves the box at x = -0.5
  EXPECT_NEAR(last.y, 0.5, 1e-12);    // the second circle leaves through the top edge
  EXPECT_LT(first.x, last.x);
}

// A criterion with a hole in its domain (throws InvalidArgument for x > 1.5, as an unconverged time average
// does): the trace keeps what it reached, says why it stopped, and every point still solves its criterion.
TEST(ZeroSet, DomainHolesEndPiecesWithANote) {
  ModeCriteria c = two_disks(1.0);
  const auto inner = c.at;
  c.at = [inner](double x, double y) {
    if (x > 1.5) throw InvalidArgument("x", "outside the test domain");
    return inner(x, y);
  };
  const ZeroSetResult r = trace_zero_set(c, PlaneBox{-2, 3, -2, 2});
  ASSERT_GE(r.chains, 1u);
  EXPECT_FALSE(r.notes.empty());
  for (const ZeroSetPiece& p : r.pieces)
    for (const ZeroSetPoint& q : p.points) {
      EXPECT_LE(q.x, 1.5);
      EXPECT_LE(std::abs(q.g), 1e-12);
    }
}

TEST(ZeroSet, NoBoundaryAndBadOptions) {
  ModeCriteria c;
  c.at = [](double, double) { return CriterionSample{{-1.0, -2.0}, 0, 0}; };
  const ZeroSetResult r = trace_zero_set(c, PlaneBox{});
  EXPECT_EQ(r.chains, 0u);
  EXPECT_TRUE(r.pieces.empty());
  ZeroSetOptions o;
  o.max_step = 0;
  EXPECT_THROW(trace_zero_set(c, PlaneBox{}, o), InvalidArgument);
  EXPECT_THROW(trace_zero_set(c, PlaneBox{0, 0, 0, 1}), InvalidArgument);
}

}  // namespace
}  // namespace rbcstab
