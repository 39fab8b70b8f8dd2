#include "rbcstab/verdict/physical_map.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <optional>
#include <thread>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/parallel.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/model/parameter_table.hpp"

namespace rbcstab {

namespace {
constexpr double kMapOutOfPlaneBeta = 1e-3;  // the paper's OP start, as the summary's search
constexpr double kWaterDensity = 1000;       // kg/m^3: plasma and the dextran media are within a few % of it
constexpr double kReynoldsBound = 0.1;       // Stokes flow: inertia below 10 % of the viscous stress

bool is_parameter_key(const std::string& key) { return key == "Delta" || key == "Delta0"; }

// Log-spaced samples over [min_rate, max_rate], samples_per_decade of them per decade, both ends included.
int sample_count(const PhysicalMapOptions& o) {
  return int(std::ceil(std::log10(o.max_rate / o.min_rate) * o.samples_per_decade)) + 1;
}

// The cell with one spread end applied; nullopt (why set) where the cell refuses the value.
std::optional<Scene> spread_cell(const Scene& scene, const std::string& key, double value, std::string& why) {
  try {
    return with_physical_value(scene, key, value);
  } catch (const InvalidArgument& e) {
    why = e.what();
    return std::nullopt;
  }
}

// The tumbling -> swinging crossing of the in-plane cell along the shear rate (first crossing from below).
RateCrossing tumbling_crossing(const Scene& cell, const PhysicalMapOptions& o, int& evaluations) {
  RateCrossing c;
  Scene base = cell;
  base.beta = kPi / 2;
  PredictorOptions regime = o.predictor;
  regime.integrator.stepper = o.regime_stepper;
  std::string why;
  // +1 past the boundary (swinging or tank-treading), 0 tumbling, nullopt undetermined (why set).
  auto past = [&](double rate) -> std::optional<bool> {
    Scene s = base;
    set_parameter(s, SceneParameter::shear_rate, rate);
    ++evaluations;
    const RegimeResult r = reduced_regime(s, regime);
    if (r.regime == Regime::tumbling) return false;
    if (r.regime == Regime::swinging || r.regime == Regime::tank_treading) return true;
    why = "regime " + to_string(r.regime) + " at " + format_value(rate) + " 1/s: " + r.reason;
    return std::nullopt;
  };
  const int n = sample_count(o);
  auto sample = [&](int k) {
    return k + 1 == n ? o.max_rate : o.min_rate * std::pow(o.max_rate / o.min_rate, double(k) / (n - 1));
  };
  double lo = o.min_rate;
  for (int k = 0; k < n; ++k) {
    const double rate = sample(k);
    const auto p = past(rate);
    if (!p) {
      c.reason = why;
      return c;
    }
    if (!*p) {
      lo = rate;
      continue;
    }
    if (k == 0) {
      c.side = "below";
      c.reason = "not tumbling already at " + format_value(o.min_rate) + " 1/s (the search's lower end)";
      return c;
    }
    double hi = rate;
    while (hi / lo - 1 > o.rtol) {
      const double mid = std::sqrt(lo * hi);
      const auto m = past(mid);
      if (!m) {
        c.reason = why;
        return c;
      }
      (*m ? hi : lo) = mid;
    }
    c.found = true;
    c.lo = lo;
    c.hi = c.rate = hi;
    return c;
  }
  c.side = "above";
  c.reason = "tumbling up to " + format_value(o.max_rate) + " 1/s (the search's upper end)";
  return c;
}

RateCrossing onset_crossing(const Scene& cell, double beta, const PhysicalMapOptions& o, int& evaluations) {
  ShearRateSearchOptions search;
  search.min_rate = o.min_rate;
  search.max_rate = o.max_rate;
  search.samples = sample_count(o);
  search.rtol = o.rtol;
  search.predictor = o.predictor;
  const ShearRateThreshold t = shear_rate_threshold(cell, beta, search);
  evaluations += t.evaluations;
  RateCrossing c;
  c.found = t.found;
  c.rate = t.shear_rate;
  c.lo = t.lo;
  c.hi = t.hi;
  c.l = t.l;
  c.reason = t.reason;
  c.side = t.side;
  return c;
}

void add_to_band(RateBand& band, const RateCrossing& c, const std::string& key) {
  ++band.cells;
  if (!c.found) return;
  if (band.found == 0 || c.rate < band.lo) band.lo = c.rate, band.lo_key = key;
  if (band.found == 0 || c.rate > band.hi) band.hi = c.rate, band.hi_key = key;
  ++band.found;
}

// One cell (nominal or a spread end) at one viscosity: its three crossings.
struct CellResult {
  bool usable = false;
  std::string why;
  RateCrossing tumbling, onset[2];
  int evaluations = 0;
};
}  // namespace

void PhysicalMapOptions::validate() const {
  require(std::isfinite(min_viscosity) && min_viscosity > 0, "min_viscosity", min_viscosity, "finite and > 0 (Pa s)");
  require(std::isfinite(max_viscosity) && max_viscosity >= min_viscosity, "max_viscosity", max_viscosity,
          ">= min_viscosity = " + format_value(min_viscosity) + " (Pa s)");
  require(viscosities >= 1 && viscosities <= 1000, "viscosities", viscosities, "an integer in [1, 1000]");
  require(viscosities == 1 || max_viscosity > min_viscosity, "viscosities", viscosities,
          "1 when min_viscosity = max_viscosity");
  require(std::isfinite(min_rate) && min_rate > 0, "min_rate", min_rate, "finite and > 0 (1/s)");
  require(std::isfinite(max_rate) && max_rate > min_rate, "max_rate", max_rate,
          "finite and > min_rate = " + format_value(min_rate) + " (1/s)");
  require(samples_per_decade >= 1 && samples_per_decade <= 100, "samples_per_decade", samples_per_decade,
          "an integer in [1, 100]");
  require(std::isfinite(rtol) && rtol >= 1e-12 && rtol <= 0.1, "rtol", rtol, "in [1e-12, 0.1]");
  require(threads >= 0 && threads <= 4096, "threads", threads, "an integer in [0, 4096] (0: all cores)");
  for (const PhysicalSpread& s : spreads)
    require(std::isfinite(s.lo) && std::isfinite(s.hi) && s.lo > 0 && s.hi > s.lo, s.key, s.hi,
            "a range 0 < lo < hi (lo = " + format_value(s.lo) + ")");
  predictor.validate();
}

Scene with_physical_value(const Scene& scene, const std::string& key, double value) {
  if (!scene.physical) throw InvalidArgument(key, key + " needs a physical scene (a [physical] table)");
  Scene s = scene;
  if (is_parameter_key(key)) {
    const bool derived = key == "Delta" ? !std::isnan(s.physical->area) : !std::isnan(s.physical->stress_free_volume);
    if (derived)
      throw InvalidArgument(key, key + " follows from the cell (" +
                                     (key == "Delta" ? std::string("area, volume") : "area, stress_free_volume") +
                                     "): spread those keys instead");
    (key == "Delta" ? s.parameters.Delta : s.parameters.Delta0) = value;
  } else {
    double& field = physical_value(*s.physical, key);
    if (std::isnan(field)) throw InvalidArgument(key, key + " is not given for this cell: it has no value to spread");
    field = value;
    s.physical->validate();
  }
  s.parameters = physical_parameters(*s.physical, s.parameters);
  s.parameters.validate();
  return s;
}

std::vector<PhysicalSpread> healthy_cell_spreads(const Scene& scene) {
  if (!scene.physical) throw InvalidArgument("spreads", "healthy-cell ranges need a physical scene");
  const PhysicalCell& c = *scene.physical;
  const std::string evans_fung = "Evans & Fung 1972, Microvasc. Res. 4:335";
  std::vector<PhysicalSpread> out = {
      {"bending_modulus", 2e-19, 9e-19, "Evans 1983; Mohandas & Evans 1994; Dimova 2014"},
      {"shear_modulus", 2.5e-6, 10e-6, "Evans & Skalak 1980; Mohandas & Evans 1994"}};
  if (!std::isnan(c.area)) {
    out.push_back({"area", 119e-12, 151e-12, evans_fung});
    out.push_back({"volume", 80e-18, 108e-18, evans_fung});
  } else if (!std::isnan(c.radius)) {
    out.push_back({"radius", 2.7e-6, 3.0e-6, evans_fung + " (R from the volume's range)"});
  }
  if (!std::isnan(c.inner_viscosity))
    out.push_back({"inner_viscosity", 5e-3, 10e-3, "Cokelet & Meiselman 1968, Science 162:275"});
  if (std::isnan(c.stress_free_volume) && scene.parameters.Delta > 0.01)
    out.push_back({"Delta0", 0.01, scene.parameters.Delta, "not measured: from near-spherical to Delta0 = Delta"});
  return out;
}

PhysicalMap physical_map(const Scene& scene, const PhysicalMapOptions& options) {
  options.validate();
  if (!scene.physical)
    throw InvalidArgument("viscosity",
                          "the physical map needs a physical scene: a [physical] table with shear_rate, "
                          "viscosity, radius (or area and volume), bending_modulus, shear_modulus and "
                          "inner_viscosity");
  (void)physical_cell(scene, "viscosity");
  if (std::isnan(scene.physical->inner_viscosity))
    throw InvalidArgument("viscosity",
                          "the physical map moves the outer viscosity, so lambda = eta_in/eta_ex must "
                          "follow it: give inner_viscosity (--inner-viscosity) instead of lambda");
  PhysicalMap map;
  map.cell = *scene.physical;
  map.min_rate = options.min_rate;
  map.max_rate = options.max_rate;
  map.onset = options.onset;
  map.spreads = options.spreads;
  // The cells: the nominal one, then each spread's two ends (one key at a time). A key must name an input this
  // cell has (checked at its nominal value, so the error names the key); an end the cell refuses (V0 < V) is
  // left out of the band, which counts the cells it was computed over.
  std::vector<std::pair<std::string, double>> cells = {{"", 0}};
  for (const PhysicalSpread& s : options.spreads) {
    if (!is_parameter_key(s.key)) (void)plausible_range(s.key);
    PhysicalCell probe = *scene.physical;
    const double nominal = s.key == "Delta"    ? scene.parameters.Delta
                           : s.key == "Delta0" ? scene.parameters.Delta0
                                               : physical_value(probe, s.key);
    (void)with_physical_value(scene, s.key, nominal);
    cells.push_back({s.key, s.lo});
    cells.push_back({s.key, s.hi});
  }
  const int nv = options.viscosities;
  std::vector<double> eta(static_cast<std::size_t>(nv));
  for (int k = 0; k < nv; ++k)
    eta[std::size_t(k)] =
        nv == 1 ? options.min_viscosity
                : options.min_viscosity * std::pow(options.max_viscosity / options.min_viscosity, double(k) / (nv - 1));
  std::vector<CellResult> results(std::size_t(nv) * cells.size());
  const int threads = options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  std::mutex progress_mutex;
  std::size_t done = 0;
  auto report = [&] {
    if (!options.on_progress) return;
    std::lock_guard lock(progress_mutex);
    options.on_progress(double(++done), double(results.size()));
  };
  parallel_for(results.size(), threads, [&](std::size_t k) {
    CellResult& r = results[k];
    const auto& [key, value] = cells[k % cells.size()];
    std::optional<Scene> cell = key.empty() ? std::optional<Scene>(scene) : spread_cell(scene, key, value, r.why);
    if (cell) cell = spread_cell(*cell, "viscosity", eta[k / cells.size()], r.why);
    if (cell) {
      r.usable = true;
      r.tumbling = tumbling_crossing(*cell, options, r.evaluations);
      if (options.onset) {
        r.onset[0] = onset_crossing(*cell, kMapOutOfPlaneBeta, options, r.evaluations);
        r.onset[1] = onset_crossing(*cell, kPi / 2, options, r.evaluations);
      }
    }
    report();
  });
  double worst_Re = 0, worst_C = 0;
  auto note_rate = [&](const Scene& s, double rate) {
    const double R = cell_numbers(*s.physical).R;
    worst_Re = std::max(worst_Re, kWaterDensity * rate * R * R / s.physical->viscosity);
    worst_C = std::max(worst_C, capillary_number(s.physical->viscosity, rate, R, s.physical->shear_modulus));
  };
  for (int v = 0; v < nv; ++v) {
    PhysicalMapColumn col;
    col.viscosity = eta[std::size_t(v)];
    std::string why;
    const Scene nominal = *spread_cell(scene, "viscosity", col.viscosity, why);
    col.lambda = nominal.parameters.lambda;
    col.Lambda = nominal.parameters.Lambda();
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const CellResult& r = results[std::size_t(v) * cells.size() + c];
      map.evaluations += r.evaluations;
      const std::string key = cells[c].first.empty() ? "" : cells[c].first + " = " + format_value(cells[c].second);
      if (c == 0) {
        col.tumbling_to_swinging = r.tumbling;
        col.onset[0] = r.onset[0];
        col.onset[1] = r.onset[1];
      }
      if (!r.usable) continue;
      add_to_band(col.tumbling_band, r.tumbling, key);
      if (options.onset)
        for (int o = 0; o < 2; ++o) add_to_band(col.onset_band[o], r.onset[o], key);
    }
    for (const RateCrossing* x : {&col.tumbling_to_swinging, &col.onset[0], &col.onset[1]})
      if (x->found) note_rate(nominal, x->rate);
    map.columns.push_back(col);
  }
  const double Delta = scene.parameters.Delta;
  map.assumptions = {
      {"quasi-spherical expansion", "Delta", Delta, 1, Delta <= 1,
       "the shape is expanded about a sphere to first order in the excess area: the neglected terms are O(Delta) "
       "relative, so at Delta = " +
           format_value(Delta) + " the boundaries are the model's, not the cell's (a real cell has Delta ~ 4)"},
      {"Stokes flow", "Re = rho gamma R^2 / eta_ex (rho = 1000 kg/m^3), largest over the reported boundaries", worst_Re,
       kReynoldsBound, worst_Re <= kReynoldsBound,
       "inertia is neglected; above Re ~ 0.1 it moves the boundaries by about Re relative"},
      {"linear shear elasticity", "C = eta_ex gamma R / mu, largest over the reported boundaries", worst_C, 1,
       worst_C <= 1,
       "membrane strains are O(C); the model's shear elasticity is linear (small strains), so above C ~ 1 the "
       "strain-stiffening of the spectrin network is missing"}};
  return map;
}

}  // namespace rbcstab
