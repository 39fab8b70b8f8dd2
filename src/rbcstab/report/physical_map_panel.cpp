// The [physical_map] figure panel (report/panels.hpp): its table read into PhysicalMapOptions, and the page's
// facts and tables made from the map and the observations drawn over it.
#include <cmath>
#include <iomanip>
#include <sstream>
#include <tuple>
#include <variant>

#include "rbcstab/core/error.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/model/physical.hpp"
#include "rbcstab/report/panels.hpp"

namespace rbcstab {

namespace {

// A [min, max] pair of a physical quantity: each item a number in SI (plausible for `quantity`, as a bare number
// anywhere) or a text with a unit. Messages name the table's key ("physical_map.viscosity").
std::pair<double, double> quantity_range(const SceneTable& t, const std::string& key, const char* quantity,
                                         PhysicalUnit unit) {
  const std::string path = t.path(key);
  const SceneTable::Value& v = t.values().at(key);
  const std::string form = path + " must be [min, max]: two " + quantity + " values 0 < min <= max, numbers in " +
                           si_unit(unit) + " or texts with a unit";
  if (v.shape != SceneTable::Value::Shape::array || v.items.size() != 2) throw InvalidArgument(path, form);
  double x[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    const SceneTable::Item& item = v.items[std::size_t(k)];
    try {
      if (const auto* text = std::get_if<std::string>(&item)) {
        x[k] = parse_quantity(*text, unit, path);
        if (!has_unit(*text)) require_plausible_bare(quantity, x[k]);
      } else if (const auto* d = std::get_if<double>(&item)) {
        x[k] = *d;
        require_plausible_bare(quantity, x[k]);
      } else if (const auto* n = std::get_if<long long>(&item)) {
        x[k] = double(*n);
        require_plausible_bare(quantity, x[k]);
      } else {
        throw InvalidArgument(path, form);
      }
    } catch (const InvalidArgument& e) {
      if (e.parameter() == path) throw;
      throw InvalidArgument(path, path + ": " + e.what());
    }
    require(std::isfinite(x[k]) && x[k] > 0, path, x[k], "finite and > 0 (" + si_unit(unit) + ")");
  }
  require(x[0] <= x[1], path, x[1], ">= its min = " + format_value(x[0]) + " " + si_unit(unit));
  return {x[0], x[1]};
}

std::string number(double v, int digits = 3) {
  std::ostringstream s;
  s << std::setprecision(digits) << v;
  return s.str();
}

// One boundary at one viscosity as the page shows it: the rate, or on which side of the searched range it lies.
std::string crossing_text(const RateCrossing& c, const PhysicalMap& map) {
  std::string out;
  if (c.found)
    out = number(c.rate) + " 1/s";
  else if (c.side == "below")
    out = "below " + number(map.min_rate) + " 1/s (the upper regime at every rate searched)";
  else if (c.side == "above")
    out = "above " + number(map.max_rate) + " 1/s (not reached)";
  else
    out = "undetermined: " + c.reason;
  if (c.l >= 3) out += ", l = " + std::to_string(c.l);
  return out;
}

std::string band_text(const RateBand& b) {
  if (b.cells <= 1) return "";
  if (b.found == 0) return "; band: found for none of " + std::to_string(b.cells) + " cells";
  return "; band " + number(b.lo) + " .. " + number(b.hi) + " 1/s (" + std::to_string(b.found) + " of " +
         std::to_string(b.cells) + " cells)";
}

std::string observed_where(const PublishedObservation& o) {
  const std::string precision = o.precision == "order" ? " (order of magnitude)" : "";
  if (o.kind == "stress") return "shear stress eta_ex gamma = " + number(o.stress) + " Pa" + precision;
  const std::string eta = "eta_ex = " + number(o.viscosity * 1e3) + " mPa s";
  if (o.kind == "point") return "gamma = " + number(o.shear_rate_lo) + " 1/s at " + eta + precision;
  return "gamma = " + number(o.shear_rate_lo) + " .. " + number(o.shear_rate_hi) + " 1/s at " + eta + precision;
}

}  // namespace

PhysicalMapPanel physical_map_panel(const SceneFile& sf) {
  PhysicalMapPanel p;
  if (!sf.physical_map) return p;
  const SceneTable& t = *sf.physical_map;
  t.allow_only({"viscosity", "viscosities", "shear_rate", "samples_per_decade", "rtol", "onset", "spreads"});
  PhysicalMapOptions& o = p.options;
  if (t.has("viscosity"))
    std::tie(o.min_viscosity, o.max_viscosity) =
        quantity_range(t, "viscosity", "viscosity", PhysicalUnit::pascal_second);
  if (t.has("shear_rate"))
    std::tie(o.min_rate, o.max_rate) = quantity_range(t, "shear_rate", "shear_rate", PhysicalUnit::per_second);
  require(o.max_rate > o.min_rate, t.path("shear_rate"), o.max_rate,
          "> its min = " + format_value(o.min_rate) + " 1/s (a range to search)");
  if (t.has("viscosities")) {
    const long long n = t.integer("viscosities");
    require(n >= 1 && n <= 1000, t.path("viscosities"), double(n), "an integer in [1, 1000]");
    o.viscosities = int(n);
  }
  if (t.has("samples_per_decade")) {
    const long long n = t.integer("samples_per_decade");
    require(n >= 1 && n <= 100, t.path("samples_per_decade"), double(n), "an integer in [1, 100]");
    o.samples_per_decade = int(n);
  }
  if (t.has("rtol")) {
    o.rtol = t.number("rtol");
    require(std::isfinite(o.rtol) && o.rtol >= 1e-12 && o.rtol <= 0.1, t.path("rtol"), o.rtol, "in [1e-12, 0.1]");
  }
  if (t.has("onset")) o.onset = t.boolean("onset");
  if (t.has("spreads")) {
    const std::string s = t.text("spreads");
    if (s != "none" && s != "healthy")
      throw InvalidArgument(t.path("spreads"), t.path("spreads") + " = '" + s + "' must be none or healthy");
    p.healthy_spreads = s == "healthy";
  }
  require(o.viscosities == 1 || o.max_viscosity > o.min_viscosity, t.path("viscosities"), o.viscosities,
          "1 when the viscosity range is a single value");
  return p;
}

PhysicalMapPage physical_map_page(const PhysicalMap& map, const std::vector<PublishedObservation>& observed,
                                  const std::string& experiments_file) {
  PhysicalMapPage page;
  const std::size_t n = map.columns.size();
  int found[3] = {0, 0, 0}, below[3] = {0, 0, 0};
  for (const PhysicalMapColumn& c : map.columns) {
    const RateCrossing* x[3] = {&c.tumbling_to_swinging, &c.onset[0], &c.onset[1]};
    for (int k = 0; k < 3; ++k) found[k] += x[k]->found, below[k] += x[k]->side == "below";
  }
  auto count = [&](int k) {
    return std::to_string(found[k]) + " of " + std::to_string(n) + " viscosities" +
           (below[k] ? "; below the range at " + std::to_string(below[k]) : "");
  };
  const bool onset = map.onset;
  page.facts = {
      {"outer viscosity eta_ex [mPa s]", n ? number(map.columns.front().viscosity * 1e3) + " .. " +
                                                 number(map.columns.back().viscosity * 1e3) + " (" + std::to_string(n) +
                                                 ", log-spaced)"
                                           : "none"},
      {"shear rates searched [1/s]", number(map.min_rate) + " .. " + number(map.max_rate)},
      {"tumbling -> swinging (in plane) found at", count(0)},
      {"bands", map.spreads.empty() ? "none computed (the nominal cell only)"
                                    : std::to_string(map.spreads.size()) + " published ranges, each at both ends"},
      {"regime and verdict evaluations", std::to_string(map.evaluations)}};
  if (onset) {
    page.facts.insert(page.facts.begin() + 3, {"l >= 3 onset, out of plane, found at", count(1)});
    page.facts.insert(page.facts.begin() + 4, {"l >= 3 onset, in plane, found at", count(2)});
  }
  page.facts.push_back(
      {"published observations",
       std::to_string(observed.size()) + " (" + (experiments_file.empty() ? "none found" : experiments_file) + ")"});

  ReportTable columns{"Boundaries per outer viscosity (nominal cell; bands where computed)",
                      {"eta_ex [mPa s]", "lambda", "Lambda", "tumbling -> swinging", "eta_ex gamma there [Pa]"},
                      {}};
  if (onset) columns.header.insert(columns.header.end(), {"l >= 3 onset, out of plane", "l >= 3 onset, in plane"});
  for (const PhysicalMapColumn& c : map.columns) {
    const RateCrossing& t = c.tumbling_to_swinging;
    std::vector<std::string> row = {number(c.viscosity * 1e3), number(c.lambda), number(c.Lambda),
                                    crossing_text(t, map) + band_text(c.tumbling_band),
                                    t.found ? number(c.viscosity * t.rate) : "-"};
    if (onset)
      for (int o = 0; o < 2; ++o) row.push_back(crossing_text(c.onset[o], map) + band_text(c.onset_band[o]));
    columns.rows.push_back(std::move(row));
  }
  page.tables.push_back(std::move(columns));

  ReportTable obs{"Published observations drawn over the map (data/experiments.csv)",
                  {"source", "observation", "where", "reference", "the statement it rests on"},
                  {}};
  for (const PublishedObservation& o : observed)
    obs.rows.push_back({o.source, o.observation, observed_where(o), o.reference, o.basis});
  page.tables.push_back(std::move(obs));

  ReportTable checks{"Where the model's assumptions fail over the map, and by how much",
                     {"assumption", "quantity", "worst value", "bound", "holds", "what a failure does"},
                     {}};
  for (const AssumptionCheck& a : map.assumptions)
    checks.rows.push_back(
        {a.assumption, a.quantity, number(a.value), number(a.bound), a.holds ? "yes" : "NO",
         a.meaning + (a.holds || a.bound <= 0 ? "" : " (" + number(a.value / a.bound, 2) + " times the bound)")});
  page.tables.push_back(std::move(checks));
  return page;
}

}  // namespace rbcstab
