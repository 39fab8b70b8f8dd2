#pragma once
// The zero set of an envelope of mode criteria in a rectangle of a plane, traced by pseudo-arclength
// continuation (continuation/continuation.hpp): the boundary max_l g_l(x, y) = 0 of the region where
// some mode grows (g_l > 0: mode l grows). Each piece is the curve g_l = 0 of one mode l, continued
// with the plane's two coordinates as (unknown, parameter), so turning points of the curve in the
// plane are passed; where another mode l' takes over (g_l' - g_l = 0, a UZ event located by the
// engine) the piece ends at a corner and the trace continues on g_l' = 0. Starts are located
// automatically: roots of the envelope on the rectangle's four edges and on interior seed lines.
// Problem-independent: rbcstab::trace_boundary supplies the physical criteria (trace.hpp), tests
// supply closed-form ones.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "rbcstab/continuation/continuation.hpp"

namespace rbcstab {

// The criteria at one point: g[l - l_min] for l = l_min .. l_min + g.size() - 1. sigma_R and alpha are
// carried into the output (0 when meaningless). May throw InvalidArgument outside the problem's domain.
struct CriterionSample {
  std::vector<double> g;
  double sigma_R = 0, alpha = 0;
};
struct ModeCriteria {
  int l_min = 3;
  std::function<CriterionSample(double x, double y)> at;
  std::string description;  // carried into each curve ("mu_l = ...")
};

struct PlaneBox {
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;  // the traced rectangle (any orientation of each axis)
};

struct ZeroSetOptions {
  int seed_lines = 4;             // interior lines x = const also searched for starts (curves not touching an edge)
  int samples = 128;              // brackets per edge or seed line: roots closer than 1/samples of it can be missed
  int bisections = 60;            // per start root: halves the bracket to ~1e-18 of the edge (then Newton polishes)
  double max_step = 0.02;         // arclength step cap in the unit square: the curve's resolution (~50 points across)
  double initial_step = 0.005;    // first step of each piece (unit square)
  double newton_tol = 1e-12;      // the engine's corrector tolerance (unit-square coordinates are O(1))
  double residual_tol = 1e-12;    // points with |g_l| above this are polished by Newton along the gradient
  double cover_tol = 2e-3;        // a start within this distance (unit square) of a traced curve is already traced
  std::size_t max_points = 5000;  // per piece
  int max_pieces = 200;           // guards against cycling between modes
  void validate() const;          // throws InvalidArgument naming the field
};

struct ZeroSetPoint {
  double x = 0, y = 0;
  int l = 3;
  double g = 0;  // g_l at the point: the residual (0 on the boundary)
  double sigma_R = 0, alpha = 0;
};
struct ZeroSetPiece {
  int l = 3;
  std::vector<ZeroSetPoint> points;  // ordered along the chain
  std::size_t chain = 0;             // pieces of one connected chain share this index, in order
};
struct ZeroSetCorner {
  double x = 0, y = 0;
  int l_from = 3, l_to = 4;  // mode before and after, along the chain
  std::size_t chain = 0;
  LocationStatus status = LocationStatus::located;
  double precision = 0;  // the engine's final bracket (unit square)
};
struct ZeroSetResult {
  std::vector<ZeroSetPiece> pieces;
  std::vector<ZeroSetCorner> corners;
  std::size_t chains = 0;
  std::size_t evaluations = 0;     // calls of criteria.at (cache misses)
  std::size_t starts = 0;          // start roots found (edges and seed lines), traced or already covered
  std::size_t turning_points = 0;  // folds of a piece in the plane (its parameter coordinate turned)
  ContinuationCounters counters;   // summed over the pieces
  std::vector<std::string> notes;  // pieces that ended other than at an edge, corner or closure (why)
};

// Chains are oriented so that x increases from the first to the last point (corners then read in
// increasing x). Deterministic.
ZeroSetResult trace_zero_set(const ModeCriteria& criteria, const PlaneBox& box, const ZeroSetOptions& options = {});

}  // namespace rbcstab
