#pragma once
// Stability boundaries traced as curves, and their agreement with simulated diagrams (issue 5,
// points 2 and 3). Criterion: the asymptotic one for out-of-plane scenes, mu_l = Upsilon_l(sigma_R^eq)
// with sigma_R^eq at the exact out-of-plane equilibrium of the reduced system (analysis/steady_states.hpp);
// mode l grows iff sigma_R^eq < sigma_l^c(alpha). The boundary is the envelope over the integer modes
// l = 3..L: the zero set of the margin m = sigma_R^eq - max_l sigma_l^c (m < 0: unstable), continued
// line by line across the plane with every root refined by bisection to full precision; on each piece the
// active mode is the argmax l, and the corners where it changes are located exactly.
#include <string>
#include <vector>

#include "rbcstab/model/scene.hpp"
#include "rbcstab/sweep/diagram.hpp"

namespace rbcstab {

struct AsymptoticVerdict {
  bool unstable = false;
  int l = 2;              // mode with the largest sigma_l^c among l = 3..L (the surviving mode) if unstable, else 2
  double sigma_R = 0;     // at the exact out-of-plane equilibrium
  double margin = 0;      // sigma_R - max_{3<=l<=L} sigma_l^c (< 0: unstable)
  int active_mode = 3;    // the argmax l of sigma_l^c (ties to the lower l)
};
// Throws InvalidArgument("beta", ...) unless the scene is out of plane (its stress-free r0 is below 1e-4).
AsymptoticVerdict asymptotic_verdict(const Scene& scene);

struct TraceOptions {
  int lines = 200;       // lines across the plane (x fixed on each); the curve's resolution
  int samples = 256;     // brackets per line: roots closer than (y range)/samples can be missed
  int bisections = 80;   // per root: halves the bracket to the last bit (|y| range / 2^80)
  void validate() const;
};

struct TracePoint {
  double x = 0, y = 0;
  int l = 3;            // active mode
  double sigma_R = 0, sigma_c = 0;
  double mu = 0;        // Upsilon_l(sigma_R^eq): the criterion's residual (0 on the boundary)
};
struct TraceCurve {
  int l = 3;                   // the mode of this piece
  std::string criterion;       // "mu_l = Upsilon_l(sigma_R^eq) = 0 (exact out-of-plane equilibrium)"
  std::vector<TracePoint> points;  // ordered along x
};
struct TraceCorner {
  double x = 0, y = 0;
  int l_from = 3, l_to = 4;    // active mode before and after (in increasing x)
};
struct TraceResult {
  std::vector<TraceCurve> curves;
  std::vector<TraceCorner> corners;
  std::size_t evaluations = 0;  // criterion evaluations
  double seconds = 0;
};

TraceResult trace_boundary(const Scene& base, const DiagramSpec& plane, const TraceOptions& options = {});

// The paper's analytic lines on the same plane, for overlay (Sec. IV, Appendix D), sampled at n values of x;
// points where a formula is outside its domain are left out. ln B - ln C planes: l_* = 2.5 and
// l_* = l + 1/2 (l = 3..L-1) as alpha lines, alpha_*^init, C_*^- (Lambda < 1) and C_*^+ (Lambda > 1, corrected
// form); ln C - lambda planes at fixed alpha: lambda_*^-(C). Other planes: none.
struct Overlay {
  std::string name;
  std::vector<double> x, y;
};
std::vector<Overlay> analytic_overlays(const Scene& base, const DiagramSpec& plane, int n = 200);

// Agreement of the asymptotic predictor with simulated points (issue 5 point 3).
struct Disagreement {
  std::size_t index = 0;
  Verdict simulated = Verdict::stable;
  int l_simulated = 2;
  bool predicted_unstable = false;
  int l_predicted = 2;
  double distance_steps = 0;  // to the nearest traced boundary point, in grid steps (max over the two axes' steps)
  double S = 0;               // the point's S (small S: far from the paper's S >> 1 regime)
  double alpha_over_alpha_init = 0;  // near 1: the initial-tension criterion competes (0 if alpha_init undefined)
};
struct Agreement {
  std::size_t points = 0;           // simulated points that finished (failed ones are excluded)
  std::size_t verdict_matches = 0;  // stable/unstable agree
  std::size_t mode_matches = 0;     // verdict agrees and, if unstable, l agrees
  std::vector<Disagreement> verdict_disagreements;
  std::size_t beyond_one_step = 0;  // verdict disagreements farther than one grid step from the boundary
};
Agreement asymptotic_agreement(const Scene& base, const DiagramSpec& spec, const std::vector<PointResult>& points,
                               const TraceResult& boundary);

}  // namespace rbcstab
