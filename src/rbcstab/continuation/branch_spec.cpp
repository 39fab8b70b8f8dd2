// BranchSpec's checks and the free parameter's bounds: lambda's and beta's closed domain edges.
#include "rbcstab/continuation/branch_spec.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "rbcstab/continuation/detail/scene_switch.hpp"
#include "rbcstab/continuation/scene_start.hpp"
#include "rbcstab/continuation/tunable_options.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {
using detail::require_switchable;
// lambda >= 0 and beta in [0, pi] are closed edges a branch lands on; other domains are open.
bool has_closed_edges(ContinuationParameter q) {
  return q == ContinuationParameter::lambda || q == ContinuationParameter::beta;
}
}  // namespace

void set_domain_bounds(ContinuationOptions& engine, ContinuationParameter q, double lo, double hi) {
  engine.p_min = lo;
  engine.p_max = hi;
  if (!has_closed_edges(q)) return;
  const Domain d = continuation_domain(q, Parameters{});  // neither domain depends on the other parameters
  engine.p_min = std::max(lo, d.lo);
  engine.p_max = std::min(hi, d.hi);
}

void require_bounds_in_domain(ContinuationParameter q, double lo, double hi, const std::string& lo_name,
                              const std::string& hi_name) {
  if (!has_closed_edges(q)) return;
  const Domain d = continuation_domain(q, Parameters{});
  const std::string range = d.text() + ", " + to_string(q) + "'s continuation domain";
  require(std::isinf(lo) || d.contains(lo), lo_name, lo, range);
  require(std::isinf(hi) || d.contains(hi), hi_name, hi, range);
}

void BranchSpec::validate() const {
  if (switch_at_bp) require_switchable(kind);
  if (is_orbit(kind)) orbit.validate();
  const ModelLevel level = model_level(kind);
  if (scene.model != ModelLevel::automatic && scene.model != level)
    throw InvalidArgument("model", "model = " + to_string(scene.model) + " is not available for --kind " +
                                       to_string(kind) + ": must be " + to_string(level) + " (or auto)");
  require(std::isfinite(relax_T) && relax_T >= 0, "relax_T", relax_T, "a finite number >= 0");
  require(label_every >= 0 && label_every <= kLabelEveryLimit, "label_every", label_every,
          integer_range(0, kLabelEveryLimit) + " (0: label only the ends and special points)");
  require(std::isfinite(relax_tol) && relax_tol > 0 && relax_tol <= 1, "relax_tol", relax_tol,
          "(0, 1] (the periodicity defect of a unit-norm state)");
  require(relax_max_periods >= 1 && relax_max_periods <= 10000000, "relax_max_periods", relax_max_periods,
          "an integer in [1, 1e7]");
  ContinuationOptions e = engine;
  set_domain_bounds(e, parameter, engine.p_min, engine.p_max);
  if (start_parameter && !start_state)
    throw InvalidArgument("start_parameter",
                          "start_parameter needs start_state (the labelled point it is the value of)");
  if (start_parameter) require(std::isfinite(*start_parameter), "start_parameter", *start_parameter, "a finite number");
  const double p_start = start_value(*this);
  if (!(p_start >= e.p_min && p_start <= e.p_max)) {
    std::ostringstream m;
    m << std::setprecision(10) << "the branch starts at the scene's " << to_string(parameter) << " = " << p_start
      << ", outside [--min, --max] = [" << e.p_min << ", " << e.p_max << "]: widen the range or change the scene";
    throw InvalidArgument("min", m.str());
  }
  e.validate();
  std::vector<std::string> names;
  for (const Monitor& m : monitors) {
    m.validate();
    for (double v : m.values.empty() ? std::vector<double>{0.0} : m.values) {
      const std::string n = monitor_event_name(m, v);
      if (std::find(names.begin(), names.end(), n) != names.end())
        throw InvalidArgument("monitor", "monitor " + n + " is given twice");
      names.push_back(n);
    }
  }
}

double start_value(const BranchSpec& spec) {
  return spec.start_parameter ? *spec.start_parameter : get_parameter(problem_scene_of(spec), spec.parameter);
}

}  // namespace rbcstab
