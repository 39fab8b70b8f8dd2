#include "rbcstab/inverse/forward.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/model/reduced_model.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

namespace {

struct FitKey {
  FitParameter id;
  const char* alias;
  bool physical;       // a physical key (plausible_range) rather than a parameter-table row
  SceneParameter row;  // the table row of a number (physical keys: the number they make, for reference only)
};
constexpr FitKey kFitKeys[] = {{FitParameter::bending_modulus, "kappa", true, SceneParameter::B},
                               {FitParameter::shear_modulus, "mu", true, SceneParameter::C},
                               {FitParameter::radius, "", true, SceneParameter::B},
                               {FitParameter::inner_viscosity, "eta_in", true, SceneParameter::lambda},
                               {FitParameter::lambda, "", false, SceneParameter::lambda},
                               {FitParameter::Delta, "", false, SceneParameter::Delta},
                               {FitParameter::Delta0, "", false, SceneParameter::Delta0}};

const FitKey& key_of(FitParameter q) {
  for (const FitKey& k : kFitKeys)
    if (k.id == q) return k;
  throw InvalidArgument("parameter", "unknown fit parameter");
}

const char* unicode_of(FitParameter q) {
  switch (q) {
    case FitParameter::bending_modulus:
      return "κ";
    case FitParameter::shear_modulus:
      return "μ";
    case FitParameter::radius:
      return "R";
    case FitParameter::inner_viscosity:
      return "η_in";
    default:
      return parameter_row(key_of(q).row).unicode;
  }
}

// Unwraps an angle sequence: each value moved by a multiple of 2 pi to within pi of the previous one.
double unwrap(double previous, double raw) { return raw + kTwoPi * std::round((previous - raw) / kTwoPi); }

// The extremum near the middle of five equally spaced samples v[0..4] of a smooth function: the interpolating
// quartic's stationary point (Newton from the parabola's vertex) as (offset in samples, value). Its error is
// O(dt^5), so the bias a sampled extremum carries (and its derivative in the parameters) stays far below the
// finite-difference and variational sensitivities' agreement (docs/inverse.md "Sensitivities").
std::pair<double, double> quartic_peak(const double v[5]) {
  // The quartic's derivatives at 0 (five-point stencils, exact for degree <= 4).
  const double d1 = (v[0] - 8 * v[1] + 8 * v[3] - v[4]) / 12;
  const double d2 = (-v[0] + 16 * v[1] - 30 * v[2] + 16 * v[3] - v[4]) / 12;
  const double d3 = (-v[0] + 2 * v[1] - 2 * v[3] + v[4]) / 2;
  const double d4 = v[0] - 4 * v[1] + 6 * v[2] - 4 * v[3] + v[4];
  double x = d2 != 0 ? std::clamp(-d1 / d2, -1.0, 1.0) : 0.0;
  for (int it = 0; it < 20; ++it) {
    const double f = d1 + x * (d2 + x * (d3 / 2 + x * d4 / 6)), fp = d2 + x * (d3 + x * d4 / 2);
    if (fp == 0) break;
    const double next = std::clamp(x - f / fp, -1.5, 1.5);
    if (std::abs(next - x) < 1e-15) break;
    x = next;
  }
  return {x, v[2] + x * (d1 + x * (d2 / 2 + x * (d3 / 6 + x * d4 / 24)))};
}

}  // namespace

void CellModel::validate() const {
  for (const FitKey& k : kFitKeys) {
    const double v = get_value(*this, k.id);
    const std::string name = to_string(k.id);
    if (!k.physical) continue;
    if (k.id == FitParameter::inner_viscosity && std::isnan(v)) continue;  // not given: lambda is held instead
    require(std::isfinite(v) && v > 0, name, v, "finite and > 0 [" + si_unit(plausible_range(name).unit) + "]");
  }
  Parameters p;
  p.lambda = lambda;
  p.Delta = Delta;
  p.Delta0 = Delta0;
  for (const FitKey& k : kFitKeys)
    if (!k.physical) require_in(k.row, parameter_domain(k.row, p), get_value(*this, k.id));
}

FitParameterInfo fit_parameter_info(FitParameter q, const CellModel& cell) {
  const FitKey& k = key_of(q);
  FitParameterInfo info;
  info.id = q;
  info.name = to_string(q);
  info.alias = k.alias;
  info.unicode = unicode_of(q);
  if (k.physical) {
    const PlausibleRange r = plausible_range(info.name);
    info.unit = si_unit(r.unit);
    info.log_scale = true;
    info.lo = r.min;
    info.hi = r.max;
  } else {
    Parameters p;
    p.lambda = cell.lambda;
    p.Delta = cell.Delta;
    p.Delta0 = cell.Delta0;
    const Domain d = parameter_domain(k.row, p).known();
    info.unit = "";
    // lambda > 0 spans decades (plasma to dextran solutions): fitted in ln with the table's range clipped to
    // [1e-3, 1e3], where Lambda(lambda) stays within the perturbative model's reach.
    info.log_scale = q == FitParameter::lambda;
    info.lo = info.log_scale ? std::max(d.lo, 1e-3) : d.lo;
    info.hi = info.log_scale ? std::min(d.hi, 1e3) : d.hi;
  }
  return info;
}

FitParameter fit_parameter_from_string(const std::string& name, const std::string& parameter) {
  std::string names;
  for (const FitKey& k : kFitKeys) {
    if (name == to_string(k.id) || (k.alias[0] != '\0' && name == k.alias)) return k.id;
    names += (names.empty() ? "" : ", ") + to_string(k.id) + (k.alias[0] ? std::string(" (") + k.alias + ")" : "");
  }
  throw InvalidArgument(parameter, parameter + " = '" + name + "' is not a fit parameter: must be one of " + names);
}

double get_value(const CellModel& cell, FitParameter q) {
  switch (q) {
    case FitParameter::bending_modulus:
      return cell.bending_modulus;
    case FitParameter::shear_modulus:
      return cell.shear_modulus;
    case FitParameter::radius:
      return cell.radius;
    case FitParameter::inner_viscosity:
      return cell.inner_viscosity;
    case FitParameter::lambda:
      return cell.lambda;
    case FitParameter::Delta:
      return cell.Delta;
    case FitParameter::Delta0:
      return cell.Delta0;
  }
  return kNotGiven;
}

void set_value(CellModel& cell, FitParameter q, double value) {
  switch (q) {
    case FitParameter::bending_modulus:
      cell.bending_modulus = value;
      break;
    case FitParameter::shear_modulus:
      cell.shear_modulus = value;
      break;
    case FitParameter::radius:
      cell.radius = value;
      break;
    case FitParameter::inner_viscosity:
      cell.inner_viscosity = value;
      break;
    case FitParameter::lambda:
      cell.lambda = value;
      break;
    case FitParameter::Delta:
      cell.Delta = value;
      break;
    case FitParameter::Delta0:
      cell.Delta0 = value;
      break;
  }
}

void apply_assignments(CellModel& cell, const std::string& text, const std::string& parameter) {
  if (text.empty()) return;
  for (const std::string& item : comma_items(text)) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
      throw InvalidArgument(parameter, parameter + " item '" + item + "' is not name=value");
    const std::string name = item.substr(0, eq), value = item.substr(eq + 1);
    const FitParameter q = fit_parameter_from_string(name, parameter);
    if (key_of(q).physical) {
      const PlausibleRange r = plausible_range(to_string(q));
      const double v = parse_quantity(value, r.unit, to_string(q));
      if (!has_unit(value)) require_plausible_bare(to_string(q), v);
      set_value(cell, q, v);
    } else {
      const std::optional<double> v = read_number(value);
      if (!v) throw InvalidArgument(to_string(q), to_string(q) + " = " + number_error(value));
      set_value(cell, q, *v);
    }
  }
}

Parameters condition_parameters(const CellModel& cell, double shear_rate, double viscosity) {
  PhysicalCell c;
  c.shear_rate = shear_rate;
  c.viscosity = viscosity;
  c.radius = cell.radius;
  c.bending_modulus = cell.bending_modulus;
  c.shear_modulus = cell.shear_modulus;
  c.inner_viscosity = cell.inner_viscosity;
  Parameters p;
  p.lambda = cell.lambda;
  p.Delta = cell.Delta;
  p.Delta0 = cell.Delta0;
  return physical_parameters(c, p);
}

void ForwardOptions::validate() const {
  require(samples_per_period >= 16 && samples_per_period <= 65536, "samples_per_period", samples_per_period,
          "an integer in [16, 65536]");
  require(block_periods >= 2 && block_periods <= 10000, "block_periods", block_periods, "an integer in [2, 10000]");
  require(max_blocks >= 1 && max_blocks <= 1000, "max_blocks", max_blocks, "an integer in [1, 1000]");
  require(periodicity_tolerance > 0 && periodicity_tolerance <= 0.1, "periodicity_tolerance", periodicity_tolerance,
          "in (0, 0.1]");
  require(rtol > 0 && rtol <= 1e-3, "rtol", rtol, "in (0, 1e-3]");
  require(transition_rtol > 0 && transition_rtol <= 0.1, "transition_rtol", transition_rtol, "in (0, 0.1]");
}

InPlaneMotion in_plane_motion(const Parameters& p, const ForwardOptions& options) {
  options.validate();
  Scene scene;
  scene.parameters = p;
  scene.beta = kPi / 2;  // the in-plane start of Sec. III (r = r0 = sqrt(3)/2, Psi = Phi = pi)
  const ValidScene valid = validated(scene);
  const ReducedModel model(p, initial_state(valid));
  IntegratorOptions io;
  io.stepper = Stepper::rk8pd;
  io.rtol = options.rtol;
  io.atol = options.rtol / 10;
  // A stiff flow (S << 1: elastic relaxation much faster than the flow) would take very many explicit steps.
  io.max_steps = 5'000'000;
  InPlaneMotion m;
  std::vector<double> y = model.initial_state();
  double t = 0, Psi = 0;
  bool first = true;
  auto psi_of = [&](std::span<const double> s) {
    const double raw = -std::atan2(s[1], s[0]);
    Psi = first ? raw : unwrap(Psi, raw);
    first = false;
    return Psi;
  };
  const int n = options.samples_per_period, coarse = 16;
  for (int block = 0; block < options.max_blocks; ++block) {
    // The block: coarse samples (enough to unwrap a rotation) over block_periods - 2 periods, then the last two
    // periods at samples_per_period for the periodicity check and the observables.
    std::vector<double> grid, samples;
    const int lead = options.block_periods - 2;
    for (int k = 1; k <= lead * coarse; ++k) grid.push_back(t + kTwoPi * k / coarse);
    const double t_window = t + kTwoPi * lead;
    for (int k = 1; k <= 2 * n; ++k) grid.push_back(t_window + kTwoPi * k / n);
    const IntegrationResult res =
        integrate(model, y, t, grid, io, [&](double, std::span<const double> s) { samples.push_back(psi_of(s)); });
    if (res.status != IntegrationStatus::success) {
      m.reason = "the reduced run failed: " + to_string(res.status) + ": " + res.reason;
      return m;
    }
    y = res.y;
    t = grid.back();
    m.periods += options.block_periods;
    const double drift = samples.back() - samples.front();
    if (std::abs(drift) > kTwoPi) {
      m.regime = Regime::tumbling;
      m.reason = "the cell tumbles: Psi rotates by " + format_value(drift) + " rad over " +
                 std::to_string(options.block_periods) + " forcing periods";
      return m;
    }
    const std::vector<double> w(samples.end() - 2 * n, samples.end());
    double defect = 0;
    for (int k = 0; k < n; ++k) defect = std::max(defect, std::abs(w[k + n] - w[k]));
    if (defect > options.periodicity_tolerance) continue;
    const std::vector<double> last(w.begin() + n, w.end());
    double mean = 0;
    for (double v : last) mean += v;  // the trapezoid rule on a periodic function: spectrally accurate
    mean /= n;
    const auto [lo, hi] = std::minmax_element(last.begin(), last.end());
    // Extrema refined on the cyclic sequence so an extremum at the window's edge keeps its neighbours.
    // Extrema refined on the cyclic sequence so an extremum at the window's edge keeps its neighbours; sample k is
    // at t - 2 pi + 2 pi (k + 1)/n, so the extremum's time after t is 2 pi (k + 1 + offset)/n mod 2 pi.
    auto peak = [&](std::size_t k) {
      double five[5];
      for (std::size_t i = 0; i < 5; ++i) five[i] = last[(k + n + i - 2) % n];
      return quartic_peak(five);
    };
    const auto k_hi = static_cast<std::size_t>(hi - last.begin()), k_lo = static_cast<std::size_t>(lo - last.begin());
    const auto [x_hi, v_hi] = peak(k_hi);
    const auto [x_lo, v_lo] = peak(k_lo);
    auto time_of = [&](std::size_t k, double x) {
      return std::fmod(kTwoPi * (static_cast<double>(k) + 1 + x) / n + kTwoPi, kTwoPi);
    };
    const double range = v_hi - v_lo;
    m.orbit_state = y;
    m.orbit_time = t;
    m.t_max = time_of(k_hi, x_hi);
    m.t_min = time_of(k_lo, x_lo);
    const double shift = kTwoPi * std::round(mean / kTwoPi);  // Psi = 2 psi in (-pi, pi]
    m.mean_psi = 0.5 * (mean - shift);
    m.amplitude_psi = 0.25 * range;
    // The reduced_regime rule: steady when Psi moves less than 1e-4 over the window.
    m.regime = range > 1e-4 ? Regime::swinging : Regime::tank_treading;
    return m;
  }
  m.reason = "the in-plane motion did not settle on a 2 pi-periodic orbit within " + format_value(m.periods) +
             " forcing periods (neither swinging nor tumbling)";
  return m;
}

Prediction predict_from_motion(const InPlaneMotion& m, const ObservedRow& row) {
  Prediction pr;
  pr.regime = m.regime;
  if (m.regime == Regime::undetermined) {
    pr.reason = m.reason;
    return pr;
  }
  if (m.regime == Regime::tumbling) {
    pr.reason = "no " + to_string(row.observable) + " predicted: " + m.reason;
    return pr;
  }
  switch (row.observable) {
    case Observable::inclination_angle:
      pr.value = m.mean_psi;
      break;
    case Observable::swinging_amplitude:
      pr.value = m.amplitude_psi;
      break;
    case Observable::swinging_frequency:
      // The swinging orbit is locked to the membrane's rotation: period 2 pi/gamma (Phi' = -1, Psi = 2 psi).
      pr.value = row.shear_rate / kTwoPi;
      break;
    case Observable::tank_treading_frequency:
      // The stress-free shape's angle phi = Phi/2 turns at gamma/2 (Eq. red_eqs: Phi' = -1).
      pr.value = row.shear_rate / (2 * kTwoPi);
      break;
    default:
      pr.reason = "not an in-plane observable";
  }
  return pr;
}

namespace {

// The transition on a fixed grid in ln S: S_j = S_lo 2^(j / 2^m), m the coarsest level whose cell is within
// transition_rtol. The answer is the cell [S_j, S_j+1] where tumbling gives way to swinging, whatever bracketed it:
// the cold route scans j by whole factors 2 from S_lo and bisects on the integers; a warm start brackets around the
// cell a previous call found at a nearby Lambda (the reduced motion depends on Lambda and S only), widening by
// doubling steps. Both end on the same cell where the regime changes once along S, so the memo changes the cost,
// never the value.
struct TransitionGrid {
  int level = 0;
  double lnS_lo = 0, step = 0;  // ln S_lo, ln 2 / 2^m
  long top = 0;                 // the index of S_hi
  double S(long j) const { return std::exp(lnS_lo + step * static_cast<double>(j)); }
};

}  // namespace

// (level, Lambda) -> the lower index of the cell found there; at most 64 entries.
struct TransitionMemo {
  mutable std::mutex lock;
  std::map<std::pair<int, double>, long> cell;
};

std::shared_ptr<TransitionMemo> make_transition_memo() { return std::make_shared<TransitionMemo>(); }

namespace {

// The warm guess at Lambda: the memo's cell at the same Lambda, else the secant through the two nearest Lambdas of
// this level (the nearest alone when only one is known). -1 when none (or no memo).
long transition_guess(const TransitionMemo* memo, int level, double Lambda) {
  if (memo == nullptr) return -1;
  std::lock_guard<std::mutex> guard(memo->lock);
  std::vector<std::pair<double, long>> near;
  for (const auto& [key, j] : memo->cell)
    if (key.first == level) near.emplace_back(key.second, j);
  if (near.empty()) return -1;
  std::sort(near.begin(), near.end(),
            [&](const auto& a, const auto& b) { return std::abs(a.first - Lambda) < std::abs(b.first - Lambda); });
  if (near[0].first == Lambda || near.size() == 1) return near[0].second;
  const auto [L0, j0] = near[0];
  const auto [L1, j1] = near[1];
  const double slope = static_cast<double>(j1 - j0) / (L1 - L0);
  return std::max(0L, j0 + std::lround(slope * (Lambda - L0)));
}

void remember_transition(TransitionMemo* memo, int level, double Lambda, long j) {
  if (memo == nullptr) return;
  std::lock_guard<std::mutex> guard(memo->lock);
  if (memo->cell.size() >= 64) memo->cell.clear();
  memo->cell[{level, Lambda}] = j;
}

Prediction predict_transition(const CellModel& cell, const ObservedRow& row, const ForwardOptions& options) {
  Prediction pr;
  const Parameters p1 = condition_parameters(cell, 1.0, row.viscosity);
  const double S1 = p1.S(), Lambda = p1.Lambda();
  // S is proportional to gamma at a fixed viscosity: scan S in [1e-2, 1e3] (below, the elastic relaxation is too
  // stiff for the explicit run and the cell tumbles; above, the memory term is a small correction) by factors 2.
  constexpr double kSlo = 1e-2, kShi = 1e3;
  TransitionGrid g;
  while (std::exp(std::log(2.0) / std::ldexp(1.0, g.level)) - 1 > options.transition_rtol) ++g.level;
  g.lnS_lo = std::log(kSlo);
  g.step = std::log(2.0) / std::ldexp(1.0, g.level);
  const long per_octave = 1L << g.level;
  g.top = static_cast<long>(std::floor(std::log(kShi / kSlo) / std::log(2.0))) * per_octave;
  std::map<long, bool> seen;
  auto tumbles = [&](long j) {
    auto it = seen.find(j);
    if (it != seen.end()) return it->second;
    const bool t =
        in_plane_motion(condition_parameters(cell, g.S(j) / S1, row.viscosity), options).regime == Regime::tumbling;
    seen.emplace(j, t);
    return t;
  };
  long lo = -1, hi = -1;
  const long guess = transition_guess(options.transition_memo.get(), g.level, Lambda);
  if (guess >= 0 && guess < g.top) {
    // Warm: widen around the guessed cell by doubling steps until [lo, hi] brackets the change.
    lo = guess;
    hi = guess + 1;
    for (long w = 1;; w *= 2) {
      const bool t_lo = tumbles(lo), t_hi = tumbles(hi);
      if (t_lo && !t_hi) break;
      const long from = t_lo ? hi : lo;  // the change lies above hi, or below lo
      hi = t_lo ? std::min(g.top, hi + w) : lo;
      lo = t_lo ? from : std::max(0L, lo - w);
      if (lo == hi) {
        lo = hi = -1;  // the grid's end: the cold scan says why
        break;
      }
    }
  }
  if (lo < 0) {
    // Cold: scan by factors 2 from S_lo.
    if (!tumbles(0)) {
      pr.reason = "no tumbling at S = " + format_value(kSlo) + " (gamma = " + format_value(kSlo / S1) + " 1/s)";
      return pr;
    }
    lo = 0;
    while (true) {
      hi = lo + per_octave;
      if (hi > g.top) {
        pr.reason = "no tumbling-to-swinging transition for S in [" + format_value(kSlo) + ", " + format_value(kShi) +
                    "] at viscosity " + format_value(row.viscosity) + " Pa s (Lambda = " + format_value(Lambda) + ")";
        return pr;
      }
      if (!tumbles(hi)) break;
      lo = hi;
    }
  }
  while (hi - lo > 1) {
    const long mid = lo + (hi - lo) / 2;
    (tumbles(mid) ? lo : hi) = mid;
  }
  remember_transition(options.transition_memo.get(), g.level, Lambda, lo);
  pr.value = std::sqrt(g.S(lo) * g.S(hi)) / S1;
  pr.regime = Regime::swinging;
  return pr;
}

Prediction predict_regime(const CellModel& cell, const ObservedRow& row, const ForwardOptions& options) {
  Prediction pr;
  Scene scene;
  scene.parameters = condition_parameters(cell, row.shear_rate, row.viscosity);
  const bool out_of_plane = row.regime == Regime::rolling || row.regime == Regime::oscillating_out_of_plane;
  if (!out_of_plane) scene.beta = kPi / 2;
  PredictorOptions po;
  po.integrator.rtol = std::max(options.rtol, 1e-10);
  const RegimeResult r = reduced_regime(scene, po);
  pr.regime = r.regime;
  if (r.regime == Regime::undetermined) pr.reason = r.reason;
  return pr;
}

}  // namespace

Prediction predict(const CellModel& cell, const ObservedRow& row, const ForwardOptions& options) {
  if (row.observable == Observable::transition_shear_rate) return predict_transition(cell, row, options);
  if (row.observable == Observable::regime) return predict_regime(cell, row, options);
  return predict_from_motion(in_plane_motion(condition_parameters(cell, row.shear_rate, row.viscosity), options), row);
}

std::vector<Prediction> predict_all(const CellModel& cell, std::span<const ObservedRow> rows,
                                    const ForwardOptions& options) {
  std::map<std::pair<double, double>, InPlaneMotion> motions;
  std::vector<Prediction> out;
  out.reserve(rows.size());
  for (const ObservedRow& row : rows) {
    if (row.observable == Observable::transition_shear_rate || row.observable == Observable::regime) {
      out.push_back(predict(cell, row, options));
      continue;
    }
    const auto key = std::make_pair(row.shear_rate, row.viscosity);
    auto it = motions.find(key);
    if (it == motions.end())
      it = motions.emplace(key, in_plane_motion(condition_parameters(cell, row.shear_rate, row.viscosity), options))
               .first;
    out.push_back(predict_from_motion(it->second, row));
  }
  return out;
}

}  // namespace rbcstab
