#pragma once
// The shear rate at which a physical cell first becomes unstable. At a fixed cell and fluid B = b gamma and
// C = c gamma (b = eta R^3/kappa, c = eta R/mu), so raising the shear rate moves the scene along the line
// ln B - ln C = ln alpha of the (ln B, ln C) plane; the threshold is where that line first enters the unstable
// region of the asymptotic verdict (verdict/asymptotic.hpp), for each rest orientation of the paper.
#include <string>
#include <string_view>
#include <vector>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/model/scene.hpp"
#include "rbcstab/verdict/asymptotic.hpp"

namespace rbcstab {

struct ShearRateSearchOptions {
  double min_rate = 1;    // 1/s: the search's lower end
  double max_rate = 1e6;  // 1/s: the upper end (far above the microcirculation's ~1e3/s)
  int samples = 36;       // log-spaced brackets over [min_rate, max_rate] (6 per decade): an unstable window
                          // narrower than one bracket can be missed
  double rtol = 1e-6;     // bisection in ln gamma until hi/lo - 1 <= rtol
  PredictorOptions predictor;
  OrbitAverageOptions orbit;
  void validate() const;  // throws InvalidArgument naming the field
};
// "LO,HI" in 1/s, each with an optional unit as for the shear rate (parse_quantity: "10/s", "1e4Hz"), into
// min_rate, max_rate; a bare number only within the shear rate's plausible range (require_plausible_bare). Throws
// InvalidArgument(name, "<name> = '<text>' ...") unless two such quantities 0 < LO < HI.
void set_search_range(ShearRateSearchOptions& options, std::string_view text, const std::string& name);
// The search options a range's text gives ("": the defaults), for the scene; refused (InvalidArgument(name, ...))
// on a scene that is not physical or for a malformed or empty range.
ShearRateSearchOptions shear_rate_search(const Scene& scene, const std::string& text, const std::string& name);

struct ShearRateThreshold {
  std::string orientation;  // "out_of_plane" (beta = 1e-3, the paper's OP) or "in_plane" (beta = pi/2)
  double beta = 0;
  bool found = false;  // a stable-to-unstable crossing within [min_rate, max_rate]
  std::string reason;  // why not found (unstable already at min_rate, stable up to max_rate, verdict failed)
  // Where the crossing lies when not found because it is outside [min_rate, max_rate]: "below" (unstable already
  // at min_rate), "above" (stable up to max_rate); "" when found or when a verdict failed (undetermined).
  std::string side;
  double shear_rate = 0;  // 1/s: the crossing (the bracket's upper end: the first rate found unstable)
  double lo = 0, hi = 0;  // the final bracket: stable at lo, unstable at hi (hi/lo - 1 <= rtol)
  double B = 0, C = 0;    // at shear_rate
  // The unstable window's upper end, when found: the first rate above shear_rate found stable again (the
  // samples after the crossing, then bisection), bracketed by end_bracket (unstable, stable; hi/lo - 1 <= rtol).
  // A stable gap narrower than one sample bracket can be missed, as a window can.
  bool end_found = false;
  double end_shear_rate = 0;       // 1/s
  double end_bracket[2] = {0, 0};  // 1/s
  std::string end_reason;          // why not found (still unstable at max_rate, verdict failed)
  double alpha = 0;                // B/C, fixed along the path
  int l = 0;                       // the surviving mode just above the threshold (asymptotic_verdict)
  std::string shape;               // the shape the paper associates with it (Sec. V, Fig. 6)
  int evaluations = 0;             // asymptotic verdicts evaluated
};

// The scene's shear rate moved along [min_rate, max_rate] (at_shear_rate: B and C together at fixed alpha), with
// beta set to the orientation's; throws InvalidArgument("shear_rate", ...) for a scene that is not physical.
ShearRateThreshold shear_rate_threshold(const Scene& scene, double beta, const ShearRateSearchOptions& options = {});
// Out of plane, then in plane.
std::vector<ShearRateThreshold> shear_rate_thresholds(const Scene& scene, const ShearRateSearchOptions& options = {});
// "stomatocyte (l = 3, out of plane)", "axisymmetric cup (l = 5, ...)", "mirror-symmetric axisymmetric shape
// (l = 4, out of plane)", "trilobe (l = 3, in plane)", "multilobe (l = 5, in plane)".
std::string shape_of_mode(int l, bool out_of_plane);

}  // namespace rbcstab
