#include "rbcstab/analysis/truncation.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {

void TruncationOptions::validate() const {
  require(std::isfinite(tolerance) && tolerance > 0 && tolerance < 1, "tolerance", tolerance, "in (0, 1)");
  require_L(L_max, 3, kMaxL, {}, "L_max");
  require(checkpoints >= 1 && checkpoints <= 10000, "checkpoints", checkpoints, "an integer in [1, 10000]");
  predictor.validate();
}

namespace {
constexpr double kNoGain = -1e300;  // log_gain of a mode that never gains area (finite, never -inf)

// Three significant digits: the reason is read by a person.
std::string short_value(double v) {
  std::ostringstream ss;
  ss << std::setprecision(3) << v;
  return ss.str();
}

// ln(d (exp(2 G) - 1)) for G > 0, d > 0, without overflow for large G.
double log_area_gain(double d, double G) { return std::log(d) + 2 * G + std::log1p(-std::exp(-2 * G)); }
}  // namespace

ReducedTransient truncation_transient(const Scene& scene, const TruncationOptions& options) {
  options.validate();
  scene.validate();
  return reduced_transient(scene, scene.T, options.checkpoints, options.predictor);
}

TruncationChoice choose_truncation(const Scene& scene, const TruncationOptions& options) {
  return choose_truncation(scene, truncation_transient(scene, options), options);
}

TruncationChoice choose_truncation(const Scene& scene, const ReducedTransient& transient,
                                   const TruncationOptions& options) {
  options.validate();
  scene.validate();
  if (!transient.of(scene) || transient.T != scene.T || transient.checkpoints != options.checkpoints)
    throw InvalidArgument("transient", "the reduced transient must be the scene's over [0, T = " + format_value(scene.T) +
                                           "] with " + std::to_string(options.checkpoints) + " checkpoints");
  Scene s = scene;
  // Every explicitly set mode must exist; L_max covers the candidates of the rule.
  int L_explicit = 2;
  for (const auto& [l, d] : scene.delta_l) L_explicit = std::max(L_explicit, l);
  for (const auto& [l, d] : scene.rest_delta_l) L_explicit = std::max(L_explicit, l);
  s.L = std::max(options.L_max, L_explicit);
  const Parameters& p = s.parameters;
  const double Delta = p.Delta;

  TruncationChoice c;
  c.G_max.assign(std::size_t(options.L_max - 2), -std::numeric_limits<double>::max());
  // G_l(t) at every checkpoint the run reached, so that a mode that grows and decays again before T counts.
  for (std::size_t k = 0; k < transient.t.size(); ++k) {
    const double t = transient.t[k];
    if (t <= 0) continue;
    const double mean_sigma = transient.integral[k] / t;
    for (int l = 3; l <= options.L_max; ++l) {
      double& G = c.G_max[std::size_t(l - 3)];
      G = std::max(G, t * Upsilon_l(p, l, mean_sigma));
    }
  }
  c.counters = transient.counters;

  std::ostringstream why;
  const double floor = std::log(options.tolerance * Delta);
  int L_needed = 2;
  c.log_gain.assign(c.G_max.size(), kNoGain);
  for (int l = 3; l <= options.L_max; ++l) {
    const double d = s.perturbation(l);
    const double G = c.G_max[std::size_t(l - 3)];
    if (d > 0 && G > 0) c.log_gain[std::size_t(l - 3)] = log_area_gain(d, G) - std::log(Delta);
    if (c.log_gain[std::size_t(l - 3)] + std::log(Delta) > floor) L_needed = l;
  }
  if (transient.status != IntegrationStatus::success) {
    c.status = DomainStatus::outside_domain;
    c.L = std::max(options.L_max, L_explicit);
    why << "L = " << c.L << " (conservative): the reduced run for the finite-horizon predictor stopped at t = "
        << format_value(transient.t_end) << " (" << transient.reason << ")";
    c.reason = why.str();
    return c;
  }
  // The lowest seeded mode stays even when nothing grows: the scene is perturbed, and the verdict needs a
  // candidate l >= 3 (it costs one mode).
  const int L_floor = s.perturbation(3) > 0 ? 3 : 2;
  c.L = std::max({L_needed, L_explicit, L_floor});
  for (int l = c.L + 1; l <= options.L_max; ++l) c.dropped_seeded_area += s.perturbation(l);

  why << "L = " << c.L << ": the smallest L keeping every mode whose linear area gain delta_l (exp(2 max_t G_l) - 1)"
      << " by T = " << format_value(s.T) << " exceeds " << short_value(options.tolerance)
      << " Delta (finite-horizon predictor)";
  if (L_needed >= 3) {
    why << "; l = " << L_needed << " grows (max_t G = " << short_value(c.G_max[std::size_t(L_needed - 3)]) << ")";
  } else {
    why << "; no mode gains";
  }
  if (c.L < options.L_max)
    why << ", l = " << c.L + 1 << " does not (max_t G = " << short_value(c.G_max[std::size_t(c.L + 1 - 3)]) << ")";
  if (L_explicit > L_needed && L_explicit == c.L) why << "; raised to the highest mode the scene sets explicitly";
  if (c.L == options.L_max && L_needed == options.L_max)
    why << "; capped at L_max: the linear predictor ignores saturation, so this is conservative";
  if (c.dropped_seeded_area > 0)
    why << "; the seeded area " << short_value(c.dropped_seeded_area) << " of l = " << c.L + 1 << ".." << options.L_max
        << " would only move to the kept modes";
  c.reason = why.str();
  return c;
}

TruncationDecision resolve_truncation(const Scene& scene, Origin L_origin, TruncationUse use,
                                      const TruncationOptions& options, const ReducedTransient* transient) {
  scene.validate();
  TruncationDecision d;
  d.L = scene.L;
  const std::string L = "L = " + std::to_string(scene.L);
  const std::string given = L_origin == Origin::flag   ? "given by --L"
                            : L_origin == Origin::file ? "given by the scene file's run.L"
                                                       : "the default";
  if (use == TruncationUse::reduced) {
    d.reason = L + " (" + given + ") is not used: the reduced system holds the l = 2 modes only";
    return d;
  }
  if (L_origin != Origin::default_value) {
    d.reason = L + ": " + given;
    return d;
  }
  const std::string unset = L + ": the default (neither --L nor run.L); ";
  switch (use) {
    case TruncationUse::simulation: {
      const TruncationChoice c = transient ? choose_truncation(scene, *transient, options) : choose_truncation(scene, options);
      d.L = c.L;
      d.reason = c.reason;
      return d;
    }
    case TruncationUse::grid:
      d.reason = unset + "one L serves every scene of the grid, while the automatic choice is made per scene";
      break;
    case TruncationUse::analysis:
      d.reason = unset + "the automatic choice bounds the truncation error of a simulation over [0, T], and this "
                         "computation has no such horizon";
      break;
    case TruncationUse::measurement: d.reason = unset + "a benchmark measures at the L it is given"; break;
    case TruncationUse::reduced: break;
  }
  return d;
}

void apply_truncation(SceneFile& file, TruncationUse use, const ReducedTransient* transient) {
  const TruncationDecision d = resolve_truncation(file.scene, file.origin("run.L"), use, {}, transient);
  file.scene.L = d.L;
  file.L_reason = d.reason;
  file.scene.validate();
}

}  // namespace rbcstab
