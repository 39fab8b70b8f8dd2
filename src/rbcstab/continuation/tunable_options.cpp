#include "rbcstab/continuation/tunable_options.hpp"

#include <array>
#include <cmath>

#include "rbcstab/core/error.hpp"
#include "rbcstab/core/text.hpp"

namespace rbcstab {

namespace {

Domain open_above(double lo) { return Domain{lo, INFINITY, false, false, {}, {}, {}, {}}; }
Domain closed(double lo, double hi) { return Domain{lo, hi, true, true, {}, {}, {}, {}}; }

// Engine fields by pointer: one accessor pair per type.
template <double ContinuationOptions::*F>
double get_e(const ContinuationOptions& e, const OrbitOptions&) {
  return e.*F;
}
template <double ContinuationOptions::*F>
void set_e(ContinuationOptions& e, OrbitOptions&, double v) {
  e.*F = v;
}
template <int ContinuationOptions::*F>
double get_ei(const ContinuationOptions& e, const OrbitOptions&) {
  return e.*F;
}
template <int ContinuationOptions::*F>
void set_ei(ContinuationOptions& e, OrbitOptions&, double v) {
  e.*F = static_cast<int>(v);
}
template <double OrbitOptions::*F>
double get_o(const ContinuationOptions&, const OrbitOptions& o) {
  return o.*F;
}
template <double OrbitOptions::*F>
void set_o(ContinuationOptions&, OrbitOptions& o, double v) {
  o.*F = v;
}
template <int OrbitOptions::*F>
double get_oi(const ContinuationOptions&, const OrbitOptions& o) {
  return o.*F;
}
template <int OrbitOptions::*F>
void set_oi(ContinuationOptions&, OrbitOptions& o, double v) {
  o.*F = static_cast<int>(v);
}

using TunedEngine = ContinuationOptions;
using TunedOrbit = OrbitOptions;

// The bounds: steps are arclengths in (x, p) (O(1) states), so any finite positive size is meaningful (their
// order, min_step <= initial_step <= max_step, is ContinuationOptions::validate's); Newton's tolerance below
// 1e-2 (above it the "solution" is not one; its residual test is sqrt(newton_tol) 1e-3); the integrator's as
// OrbitOptions needs for Floquet multipliers.
// A function's static: the CLI's registration reads the table during static initialisation.
const std::array<TunableOption, 10>& options_table() {
  static const std::array<TunableOption, 10> kOptions{{
      {"initial_step", "--step", "first arclength step (AUTO's DS)", open_above(0), false, false,
       get_e<&TunedEngine::initial_step>, set_e<&TunedEngine::initial_step>},
      {"min_step", "--min-step",
       "smallest arclength step (DSMIN): a corrector that fails below it ends the run (step_too_small)", open_above(0),
       false, false, get_e<&TunedEngine::min_step>, set_e<&TunedEngine::min_step>},
      {"max_step", "--max-step", "largest arclength step (DSMAX)", open_above(0), false, false,
       get_e<&TunedEngine::max_step>, set_e<&TunedEngine::max_step>},
      {"newton_tol", "--newton-tol",
       "Newton's tolerance (EPSL/EPSU): on max|dX| relative to 1 + max|X|, and sqrt(newton_tol) 1e-3 on max|F|",
       Domain{0, 1e-2, false, false, {}, {}, {}, {}}, false, false, get_e<&TunedEngine::newton_tol>,
       set_e<&TunedEngine::newton_tol>},
      {"max_newton", "--max-newton", "Newton iterations per corrector (ITNW)", closed(2, 100), true, false,
       get_ei<&TunedEngine::max_newton>, set_ei<&TunedEngine::max_newton>},
      {"location_tol", "--location-tol",
       "special points and monitors are located until their bracket spans less than this in (x, p) (EPSS)",
       Domain{0, 1e-2, false, true, {}, {}, {}, {}}, false, false, get_e<&TunedEngine::location_tol>,
       set_e<&TunedEngine::location_tol>},
      {"segments", "--segments",
       "orbits: multiple-shooting segments (AUTO's NTST; there is no NCOL: inside a segment the integration tolerance "
       "sets the resolution); a restart keeps the run's",
       closed(1, 1000), true, true, get_oi<&TunedOrbit::segments>, set_oi<&TunedOrbit::segments>},
      {"orbit_rtol", "--orbit-rtol",
       "orbits: the relative tolerance of each segment's integration (with its variational equations)",
       Domain{1e-15, 1e-6, true, true, {}, {}, {}, "Floquet multipliers need a tight tolerance"}, false, true,
       get_o<&TunedOrbit::rtol>, set_o<&TunedOrbit::rtol>},
      {"orbit_atol", "--orbit-atol", "orbits: the absolute tolerance of each segment's integration (states are O(1))",
       Domain{0, 1e-6, false, true, {}, {}, {}, {}}, false, true, get_o<&TunedOrbit::atol>, set_o<&TunedOrbit::atol>},
      {"orbit_samples", "--orbit-samples", "orbits: dense samples per segment that seed r_min, r_max, Psi_min, Psi_max",
       Domain{4, 100000, true, true, {}, "100000", {}, {}}, true, true, get_oi<&TunedOrbit::samples_per_segment>,
       set_oi<&TunedOrbit::samples_per_segment>},
  }};
  return kOptions;
}

}  // namespace

std::string TunableOption::keyword() const {
  std::string k = std::string(flag).substr(2);
  for (char& c : k)
    if (c == '-') c = '_';
  return k;
}

std::string TunableOption::range() const {
  const std::string d = domain.text();
  return integer ? "an integer " + d : d;
}

double TunableOption::default_value() const { return get(ContinuationOptions{}, OrbitOptions{}); }

void TunableOption::check(double value) const {
  require(domain.contains(value) && std::isfinite(value) && (!integer || value == std::floor(value)), name, value,
          range());
}

std::span<const TunableOption> tunable_options() { return options_table(); }

const TunableOption& tunable_option(std::string_view name) {
  std::string names;
  for (const TunableOption& o : options_table()) {
    if (o.name == name) return o;
    names += (names.empty() ? "" : ", ") + std::string(o.name);
  }
  throw InvalidArgument("option", "unknown option '" + std::string(name) + "' (options: " + names + ")");
}

}  // namespace rbcstab
