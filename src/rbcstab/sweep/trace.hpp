#pragma once
// Stability boundaries traced as curves. Criteria, per mode l = 3..L
// (g_l > 0: mode l grows), the verdicts of rbcstab::verdict:
//  - asymptotic: mu_l = Upsilon_l(<sigma_R>) on the reduced attractor: the exact out-of-plane equilibrium
//    for out-of-plane scenes; in plane the period average over the attracting 2 pi-periodic orbit, or a
//    converged time average of sigma_R where the attractor is not such an orbit (verdict/asymptotic.hpp);
//  - finite horizon: G_l(T) = int_0^T Upsilon_l(sigma_R(t)) dt along the reduced transient
//    (analysis finite_horizon_growth, verdict finite_horizon_prediction).
// The boundary is the zero set of the envelope max_l g_l, traced by pseudo-arclength continuation of
// g_l = 0 from automatically located starts, with the corners where another mode takes over located as
// engine events (sweep/zero_set.hpp). On a ln B plane the finite-horizon and the in-plane asymptotic boundaries
// are instead traced in closed form in B (TraceMethod::automatic): the same boundary, with one reduced transient
// or periodic orbit per value of the other axis.
#include <string>
#include <string_view>
#include <vector>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/core/progress.hpp"
#include "rbcstab/model/scene.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/zero_set.hpp"
#include "rbcstab/verdict/asymptotic.hpp"

namespace rbcstab {

enum class TraceCriterion { asymptotic, finite_horizon };
// Outputs write "finite-horizon"; input also takes the enumerator's spelling "finite_horizon".
template <>
struct EnumTable<TraceCriterion> {
  static constexpr EnumName<TraceCriterion> entries[] = {{TraceCriterion::asymptotic, "asymptotic"},
                                                         {TraceCriterion::finite_horizon, "finite-horizon"},
                                                         {TraceCriterion::finite_horizon, "finite_horizon"}};
};
// Throws InvalidArgument("criterion", ...) naming the allowed criteria.
inline TraceCriterion trace_criterion_from_string(std::string_view name) {
  return from_string<TraceCriterion>(name, "criterion");
}

// How a boundary is traced. automatic: on a plane with a ln B axis whose other axis leaves B (and no fixed alpha), the
// finite-horizon boundary and the in-plane asymptotic one in closed form in B, one reduced transient or periodic
// orbit per value of the other axis (the reduced flow holds no B), falling back to continuation if some value has
// none; every other plane by continuation. continuation: continuation on every plane (comparisons).
enum class TraceMethod { automatic, continuation };
template <>
struct EnumTable<TraceMethod> {
  static constexpr EnumName<TraceMethod> entries[] = {{TraceMethod::automatic, "auto"},
                                                      {TraceMethod::continuation, "continuation"}};
};
// Throws InvalidArgument("method", ...) naming the allowed methods.
inline TraceMethod trace_method_from_string(std::string_view name) { return from_string<TraceMethod>(name, "method"); }

struct TraceOptions {
  TraceCriterion criterion = TraceCriterion::asymptotic;
  double T = 0;            // finite horizon; 0: the scene's T
  int lines = 4;           // interior lines x = const searched for starts, besides the plane's four edges
  int samples = 128;       // brackets per edge or line: start roots closer than 1/samples of it can be missed
  int bisections = 60;     // per start root (to the last bit; Newton then polishes)
  double max_step = 0.02;  // arclength step cap in the unit square: the curve's resolution
  // Reduced runs of the finite-horizon and in-plane criteria: rk8pd at rtol 1e-12 (analysis default 1e-10),
  // because Newton needs the criterion smooth below the 1e-10 residual it is traced to (at 1e-10 the step
  // selection leaves ~1e-10 jitter in G_l(T) = 500 Upsilon_l; measured); costs ~1.7x per evaluation.
  PredictorOptions predictor = tracing_predictor();
  OrbitAverageOptions orbit;  // in-plane asymptotic criterion: periodic-orbit average (time average as fallback)
  TraceMethod method = TraceMethod::automatic;
  ProgressCallback on_progress;  // criterion evaluations so far (total unknown: 0)
  void validate() const;
  static PredictorOptions tracing_predictor();
  ZeroSetOptions zero_set() const;
};

// The criteria g_l(x, y) of a plane (mu_l or G_l(T) for l = 3..L), as traced.
ModeCriteria plane_criteria(const Scene& base, const DiagramSpec& plane, const TraceOptions& options);

struct TracePoint {
  double x = 0, y = 0;
  int l = 3;                        // active mode
  double sigma_R = 0, sigma_c = 0;  // <sigma_R> (asymptotic) or <sigma_R>_T (finite horizon); sigma_l^c(alpha)
  double mu = 0;  // the criterion's residual g_l: mu_l (asymptotic) or G_l(T) (finite horizon); 0 on the boundary
};
struct TraceCurve {
  int l = 3;                       // the mode of this piece
  std::string criterion;           // e.g. "mu_l = Upsilon_l(sigma_R^eq) = 0 (...)"
  std::vector<TracePoint> points;  // ordered along the curve (each chain runs towards increasing x)
  std::size_t chain = 0;           // pieces of one connected curve share this index
};
struct TraceCorner {
  double x = 0, y = 0;
  int l_from = 3, l_to = 4;  // active mode before and after (along the chain, i.e. towards increasing x)
};
struct TraceResult {
  std::vector<TraceCurve> curves;
  std::vector<TraceCorner> corners;
  std::size_t evaluations = 0;  // criterion evaluations (closed form in B: periodic orbits solved)
  double seconds = 0;
  TraceCriterion criterion = TraceCriterion::asymptotic;
  std::size_t chains = 0, starts = 0, turning_points = 0;
  ContinuationCounters counters;   // the engine's work
  std::vector<std::string> notes;  // pieces that ended inside the plane, and why; a fallback from the closed form
  std::string method = "by continuation";  // or "in closed form in B" (TraceMethod::automatic where it applies)
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

}  // namespace rbcstab
