#include "rbcstab/verdict/shear_rate.hpp"

#include <cmath>
#include <numbers>
#include <optional>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/model/parameter_table.hpp"

namespace rbcstab {

namespace {
constexpr double kOutOfPlaneBeta = 1e-3;  // the paper's OP start (Sec. IV): beta = 0 is singular for the reduced system
}  // namespace

void ShearRateSearchOptions::validate() const {
  require(std::isfinite(min_rate) && min_rate > 0, "min_rate", min_rate, "finite and > 0 (1/s)");
  require(std::isfinite(max_rate) && max_rate > min_rate, "max_rate", max_rate,
          "finite and > min_rate = " + format_value(min_rate));
  require(samples >= 2 && samples <= 10000, "samples", samples, "an integer in [2, 10000]");
  require(std::isfinite(rtol) && rtol >= 1e-14 && rtol <= 0.1, "rtol", rtol, "in [1e-14, 0.1]");
  orbit.validate();
}

void set_search_range(ShearRateSearchOptions& options, std::string_view text, const std::string& name) {
  const std::string form = name + " = '" + std::string(text) + "' must be LO,HI: two shear rates 0 < LO < HI in 1/s";
  const std::vector<std::string> parts = comma_items(std::string(text));
  if (parts.size() != 2) throw InvalidArgument(name, form);
  double range[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    try {
      range[k] = parse_quantity(parts[std::size_t(k)], PhysicalUnit::per_second, name);
      // A bare number is a shear rate in 1/s only where one is plausible, as for --shear-rate.
      if (!has_unit(parts[std::size_t(k)])) require_plausible_bare("shear_rate", range[k]);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(name, form + " (" + e.what() + ")");
    }
  }
  if (!(range[0] < range[1])) throw InvalidArgument(name, form + " (LO >= HI)");
  options.min_rate = range[0];
  options.max_rate = range[1];
}

std::string shape_of_mode(int l, bool out_of_plane) {
  const std::string mode = "l = " + std::to_string(l);
  // Out of plane the mode is axisymmetric about the vorticity axis z (m = 0: the start's symmetry, Sec. V), and
  // Y_l0 has parity (-1)^l under z -> -z: odd l bulge one way (a cup; l = 3 the paper's stomatocyte), even l are
  // mirror-symmetric about the shear plane (no cup).
  if (out_of_plane) {
    const std::string name = l == 3       ? "stomatocyte"
                             : l % 2 == 1 ? "axisymmetric cup"
                                          : "mirror-symmetric axisymmetric shape";
    return name + " (" + mode + ", out of plane)";
  }
  return l == 3 ? "trilobe (" + mode + ", in plane)" : "multilobe (" + mode + ", in plane)";
}

ShearRateThreshold shear_rate_threshold(const Scene& scene, double beta, const ShearRateSearchOptions& options) {
  options.validate();
  require_usable(SceneParameter::shear_rate, scene);
  ShearRateThreshold t;
  t.beta = beta;
  t.orientation = beta == kOutOfPlaneBeta ? "out_of_plane" : "in_plane";
  t.alpha = scene.parameters.alpha();
  Scene base = scene, s;
  base.beta = beta;
  // The verdict at one rate; nullopt where <sigma_R> has no value (the time average did not converge). Each
  // rate is set from the base scene, so B and C carry one rounding however long the search.
  auto verdict = [&](double rate, std::string& why) -> std::optional<AsymptoticVerdict> {
    s = base;
    set_parameter(s, SceneParameter::shear_rate, rate);
    ++t.evaluations;
    try {
      return asymptotic_verdict(s, options.predictor, options.orbit);
    } catch (const InvalidArgument& e) {
      why = "asymptotic verdict undefined at shear_rate = " + format_value(rate) + " 1/s: " + e.what();
      return std::nullopt;
    }
  };
  // Bisection in ln gamma of [a, b] whose ends differ in stability, to hi/lo - 1 <= rtol; the unstable end's
  // verdict kept in `at_unstable`. False (t.reason set) where a verdict fails.
  auto bisect = [&](double& a, double& b, bool a_unstable, AsymptoticVerdict& at_unstable, std::string& why) {
    while (b / a - 1 > options.rtol) {
      const double mid = std::sqrt(a * b);
      const auto m = verdict(mid, why);
      if (!m) return false;
      if (m->unstable) at_unstable = *m;
      (m->unstable == a_unstable ? a : b) = mid;
    }
    return true;
  };
  const double a = std::log(options.min_rate), b = std::log(options.max_rate);
  auto sample = [&](int k) {
    return k + 1 == options.samples ? options.max_rate : std::exp(a + (b - a) * k / (options.samples - 1));
  };
  std::string why;
  // The window's upper end, from sample k (unstable) on: the first later sample found stable again, then
  // bisection down to the flip.
  auto find_end = [&](int k) {
    double last_unstable = sample(k);
    for (int j = k + 1; j < options.samples; ++j) {
      const double r = sample(j);
      const auto w = verdict(r, why);
      if (!w) {
        t.end_reason = why;
        return;
      }
      if (w->unstable) {
        last_unstable = r;
        continue;
      }
      double end_lo = last_unstable, end_hi = r;
      AsymptoticVerdict at_end = *w;
      if (!bisect(end_lo, end_hi, true, at_end, why)) {
        t.end_reason = why;
        return;
      }
      t.end_found = true;
      t.end_bracket[0] = end_lo;
      t.end_bracket[1] = t.end_shear_rate = end_hi;
      return;
    }
    t.end_reason = "unstable up to max_rate = " + format_value(options.max_rate) + " 1/s (the search's end)";
  };
  double lo = options.min_rate;
  for (int k = 0; k < options.samples; ++k) {
    const double rate = sample(k);
    const auto v = verdict(rate, why);
    if (!v) {
      t.reason = why;
      return t;
    }
    if (!v->unstable) {
      lo = rate;
      continue;
    }
    if (k == 0) {
      t.reason = "unstable already at min_rate = " + format_value(options.min_rate) + " 1/s";
      t.side = "below";
      t.l = v->l;
      t.shape = shape_of_mode(v->l, t.orientation == "out_of_plane");
      find_end(0);
      return t;
    }
    double hi = rate;
    AsymptoticVerdict at_hi = *v;
    if (!bisect(lo, hi, false, at_hi, why)) {
      t.reason = why;
      return t;
    }
    s = base;
    set_parameter(s, SceneParameter::shear_rate, hi);
    t.found = true;
    t.lo = lo;
    t.hi = t.shear_rate = hi;
    t.B = s.parameters.B;
    t.C = s.parameters.C;
    t.l = at_hi.l;
    t.shape = shape_of_mode(t.l, t.orientation == "out_of_plane");
    find_end(k);
    return t;
  }
  t.reason = "stable up to max_rate = " + format_value(options.max_rate) + " 1/s";
  t.side = "above";
  return t;
}

std::vector<ShearRateThreshold> shear_rate_thresholds(const Scene& scene, const ShearRateSearchOptions& options) {
  return {shear_rate_threshold(scene, kOutOfPlaneBeta, options), shear_rate_threshold(scene, kPi / 2, options)};
}

ShearRateSearchOptions shear_rate_search(const Scene& scene, const std::string& text, const std::string& name) {
  ShearRateSearchOptions search;
  if (text.empty()) return search;
  (void)physical_cell(scene, name);
  set_search_range(search, text, name);
  search.validate();
  return search;
}

}  // namespace rbcstab
