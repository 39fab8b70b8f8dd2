#include "rbcstab/model/parameter_table.hpp"

#include <array>
#include <numbers>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {
using P = SceneParameter;
constexpr std::uint32_t bit(P q) { return 1u << static_cast<unsigned>(q); }
constexpr double kInf = INFINITY;

Domain open_above(double lo, bool closed) { return Domain{lo, kInf, closed, false, "", "", "", ""}; }
// The cell's shear rate, moved along its line B = b gamma, C = c gamma (at_shear_rate): alpha stays.
double get_shear_rate(const Scene& s) { return physical_cell(s, "shear_rate").shear_rate; }
void set_shear_rate(Scene& s, double v) {
  s.parameters = at_shear_rate(physical_cell(s, "shear_rate"), s.parameters, v);
  s.physical->shear_rate = v;
}

Domain up_to_Delta(const Parameters& p) {
  return Domain{0, p.Delta, true, true, "", "Delta", "Delta = " + format_value(p.Delta), ""};
}

constexpr unsigned kEvery = kEveryLevel, kAboveTwo = kModesAboveTwo;

// One row per SceneParameter, in its order (tests/model/parameter_table_test.cpp checks it).
const std::array<ParameterRow, 13> kTable{{
    {.id = P::lambda,
     .name = "lambda",
     .symbol = "\\lambda",
     .unicode = "λ",
     .description = "viscosity ratio eta_in/eta_ex",
     .table = "parameters",
     .scale = AxisScale::linear,
     .of = P::lambda,
     .moves = P::lambda,
     .inputs = bit(P::lambda),
     .levels = kEvery,
     .continuation = true,
     .axis = true,
     .physical = {"eta_in / eta_ex", "Sec. II", [](const CellNumbers& n) { return n.lambda; }, "the inner viscosity",
                  &UnitsQuery::lambda},
     .domain = [](const Parameters&) { return open_above(0, true); },
     .get = [](const Scene& s) { return s.parameters.lambda; },
     .set = [](Scene& s, double v) { s.parameters.lambda = v; }},
    {.id = P::Delta,
     .name = "Delta",
     .symbol = "\\Delta",
     .unicode = "Δ",
     .description = "excess area of the current shape",
     .table = "parameters",
     .scale = AxisScale::linear,
     .of = P::Delta,
     .moves = P::Delta,
     .inputs = bit(P::Delta),
     .levels = kEvery,
     .continuation = true,
     .axis = true,
     .physical = {"A/R^2 - 4 pi", "Sec. II, Fig. 1", [](const CellNumbers& n) { return n.Delta; }, "the area",
                  &UnitsQuery::Delta},
     .domain = [](const Parameters&) { return Domain{0, 4 * kPi, false, false, "", "4 pi", "", ""}; },
     .get = [](const Scene& s) { return s.parameters.Delta; },
     .set = [](Scene& s, double v) { s.parameters.Delta = v; }},
    {.id = P::Delta0,
     .name = "Delta0",
     .symbol = "\\Delta_0",
     .unicode = "Δ₀",
     .description = "excess area of the stress-free shape (0: the vesicle limit)",
     .table = "parameters",
     .scale = AxisScale::linear,
     .of = P::Delta0,
     .moves = P::Delta0,
     .inputs = bit(P::Delta0),
     .levels = kEvery,
     .continuation = true,
     .axis = true,
     .physical = {"A/R0^2 - 4 pi, R0 = (3 V0/(4 pi))^(1/3)", "Sec. II, Fig. 1",
                  [](const CellNumbers& n) { return n.Delta0; }, "the stress-free volume", &UnitsQuery::Delta0},
     .domain = up_to_Delta,
     .get = [](const Scene& s) { return s.parameters.Delta0; },
     .set = [](Scene& s, double v) { s.parameters.Delta0 = v; }},
    {.id = P::B,
     .name = "B",
     .symbol = "\\mathcal{B}",
     .unicode = "B",
     .description = "bending number eta gamma R^3 / kappa",
     .table = "parameters",
     .scale = AxisScale::linear,
     .of = P::B,
     .moves = P::B,
     .inputs = bit(P::B),
     .levels = kAboveTwo,
     .continuation = true,
     .axis = false,
     .physical = {"eta_ex gamma R^3 / kappa", "Eq. (dimless_nums)", [](const CellNumbers& n) { return n.B; },
                  "the shear rate", &UnitsQuery::B},
     .domain = [](const Parameters&) { return open_above(0, false); },
     .get = [](const Scene& s) { return s.parameters.B; },
     .set = [](Scene& s, double v) { s.parameters.B = v; }},
    {.id = P::C,
     .name = "C",
     .symbol = "\\mathcal{C}",
     .unicode = "C",
     .description = "capillary number eta gamma R / mu",
     .table = "parameters",
     .scale = AxisScale::linear,
     .of = P::C,
     .moves = P::C,
     .inputs = bit(P::C),
     .levels = kEvery,
     .continuation = true,
     .axis = false,
     .physical = {"eta_ex gamma R / mu", "Eq. (dimless_nums)", [](const CellNumbers& n) { return n.C; },
                  "the shear rate, or the shear modulus when B is given too", &UnitsQuery::C},
     .domain =
         [](const Parameters&) { return Domain{0, kInf, false, true, "", "", "", "inf allowed: the vesicle limit"}; },
     .get = [](const Scene& s) { return s.parameters.C; },
     .set = [](Scene& s, double v) { s.parameters.C = v; }},
    // The composites of the reduced system (Eq. Lambda_S) each move one input, so they move alone: Lambda
    // ~ sqrt(Delta) at fixed lambda (S unchanged), S ~ C at fixed Delta0 (Lambda unchanged).
    {.id = P::Lambda,
     .name = "Lambda",
     .symbol = "\\Lambda",
     .unicode = "Λ",
     .description = "sqrt(Delta)(23 lambda + 32)/(8 sqrt(30 pi)) of the reduced system, set through Delta",
     .table = nullptr,
     .scale = AxisScale::linear,
     .of = P::Lambda,
     .moves = P::Delta,
     .inputs = bit(P::Delta) | bit(P::lambda),
     .levels = kEvery,
     .continuation = true,
     .axis = false,
     .definition = "sqrt(Delta)(23 lambda + 32)/(8 sqrt(30 pi))",
     .physical = {"sqrt(Delta) (23 lambda + 32) / (8 sqrt(30 pi))", "Eq. (Lambda_S)",
                  [](const CellNumbers& n) { return cell_parameters(n).Lambda(); }},
     .domain = [](const Parameters&) { return open_above(0, false); },
     .get = [](const Scene& s) { return s.parameters.Lambda(); },
     .set =
         [](Scene& s, double v) {
           const double ratio = v / s.parameters.Lambda();
           s.parameters.Delta *= ratio * ratio;
         }},
    {.id = P::S,
     .name = "S",
     .symbol = "S",
     .unicode = "S",
     .description = "C sqrt(15 pi/(2 Delta0)) of the reduced system, set through C",
     .table = nullptr,
     .scale = AxisScale::linear,
     .of = P::S,
     .moves = P::C,
     .inputs = bit(P::C) | bit(P::Delta0),
     .levels = kEvery,
     .continuation = true,
     .axis = false,
     .definition = "C sqrt(15 pi/(2 Delta0))",
     .physical = {"C sqrt(15 pi / (2 Delta0))", "Eq. (Lambda_S)",
                  [](const CellNumbers& n) {
                    return std::isnan(n.C) || std::isnan(n.Delta0) ? kNotGiven : cell_parameters(n).S();
                  }},
     .domain = [](const Parameters&) { return open_above(0, false); },
     .get = [](const Scene& s) { return s.parameters.S(); },
     .set =
         [](Scene& s, double v) {
           const double S = s.parameters.S();
           require(std::isfinite(S), "S", v, "continuable only from a finite S (Delta0 > 0 and C finite)");
           s.parameters.C *= v / S;
         }},
    // alpha = mu R^2/kappa needs no flow: the cell gives it from its moduli and size alone.
    {.id = P::alpha,
     .name = "alpha",
     .symbol = "\\alpha",
     .unicode = "α",
     .description = "B/C = mu R^2/kappa, set through B",
     .table = nullptr,
     .scale = AxisScale::linear,
     .of = P::alpha,
     .moves = P::B,
     .inputs = bit(P::B) | bit(P::C),
     .levels = kAboveTwo,
     .continuation = false,
     .axis = true,
     .definition = "B/C",
     .physical = {"B/C = mu R^2 / kappa", "after Eq. (inst)", [](const CellNumbers& n) { return n.alpha; },
                  "the shear modulus", &UnitsQuery::alpha},
     .domain = [](const Parameters&) { return open_above(0, false); },
     .get = [](const Scene& s) { return s.parameters.alpha(); },
     .set = [](Scene& s, double v) { s.parameters.B = v * s.parameters.C; }},
    {.id = P::lnB,
     .name = "lnB",
     .symbol = "\\ln \\mathcal{B}",
     .unicode = "ln B",
     .description = "ln B, a log axis of the bending number",
     .table = nullptr,
     .scale = AxisScale::log,
     .of = P::B,
     .moves = P::B,
     .inputs = bit(P::B),
     .levels = kAboveTwo,
     .continuation = false,
     .axis = true},
    {.id = P::lnC,
     .name = "lnC",
     .symbol = "\\ln \\mathcal{C}",
     .unicode = "ln C",
     .description = "ln C, a log axis of the capillary number",
     .table = nullptr,
     .scale = AxisScale::log,
     .of = P::C,
     .moves = P::C,
     .inputs = bit(P::C),
     .levels = kEvery,
     .continuation = false,
     .axis = true},
    {.id = P::beta,
     .name = "beta",
     .symbol = "\\beta",
     .unicode = "β",
     .description = "rotation of the axisymmetric shapes about y (pi/2 = 1.5707963267948966)",
     .table = "initial",
     .scale = AxisScale::linear,
     .of = P::beta,
     .moves = P::beta,
     .inputs = bit(P::beta),
     .levels = kEvery,
     .continuation = true,
     .axis = true,
     .domain =
         [](const Parameters&) {
           return Domain{0, kPi, true, true, "", "pi", "", "0: rest shape out of plane, pi/2: in plane"};
         },
     .get = [](const Scene& s) { return s.beta; },
     .set = [](Scene& s, double v) { s.beta = v; }},
    {.id = P::delta,
     .name = "delta",
     .symbol = "\\delta",
     .unicode = "δ",
     .description = "perturbation Delta_l(0) put in f_{l,0} for every l = 3..L",
     .table = "initial",
     .scale = AxisScale::linear,
     .of = P::delta,
     .moves = P::delta,
     .inputs = bit(P::delta),
     .levels = kAboveTwo,
     .continuation = false,
     .axis = false,
     .domain = up_to_Delta,
     .get = [](const Scene& s) { return s.delta; },
     .set = [](Scene& s, double v) { s.delta = v; }},
    // Stored in the physical cell, whose table ([physical], io/scene_file.hpp) declares its key and flag
    // (--shear-rate) with the cell's other quantities from this row's name, description and domain.
    {.id = P::shear_rate,
     .name = "shear_rate",
     .symbol = "\\dot\\gamma",
     .unicode = "γ̇",
     .unit = "1/s",
     .description = "shear rate gamma [1/s]; B and C follow at fixed alpha (a physical scene; time unit 1/gamma)",
     .table = nullptr,
     .scale = AxisScale::geometric,
     .of = P::shear_rate,
     .moves = P::shear_rate,
     .inputs = bit(P::shear_rate) | bit(P::B) | bit(P::C),
     .levels = kEvery,
     .continuation = true,
     .axis = true,
     .domain = [](const Parameters&) { return Domain{0, kInf, false, false, "", "", "", "1/s"}; },
     .get = get_shear_rate,
     .set = set_shear_rate},
}};

// A log row's domain: its base's, mapped by ln (ln 0 = -inf).
Domain log_of(const Domain& d) {
  auto name = [](const std::string& n) { return n.empty() ? n : "ln(" + n + ")"; };
  return Domain{std::log(d.lo),  std::log(d.hi),  d.lo_closed, d.hi_closed,
                name(d.lo_name), name(d.hi_name), d.where,     d.note};
}

// How a message names a value of this use ("parameter = 'x'") and what it is not ("a continuation parameter").
struct UseWords {
  const char* name;
  const char* noun;
};
UseWords words(ParameterUse use) {
  switch (use) {
    case ParameterUse::scene_key:
      return {"key", "scene parameter"};
    case ParameterUse::continuation:
      return {"parameter", "continuation parameter"};
    case ParameterUse::axis:
      return {"axis", "diagram axis"};
  }
  return {"parameter", "parameter"};
}
}  // namespace

Domain Domain::known() const {
  Domain d = *this;
  if (std::isnan(d.lo)) d = Domain{-kInf, d.hi, false, d.hi_closed, "", d.hi_name, "", d.note};
  if (std::isnan(d.hi)) d = Domain{d.lo, kInf, d.lo_closed, false, d.lo_name, "", "", d.note};
  return d;
}

bool Domain::contains(double v) const {
  if (std::isnan(v) || v < lo || v > hi) return false;
  return (v != lo || lo_closed) && (v != hi || hi_closed);
}

std::string Domain::text(bool with_where) const {
  auto bound = [](double v, const std::string& name) { return name.empty() ? format_value(v) : name; };
  const bool lo_inf = std::isinf(lo), hi_inf = std::isinf(hi);
  std::string t;
  if (lo_inf && hi_inf)
    t = lo_closed || hi_closed ? "a number" : "finite";
  else if (hi_inf)
    t = std::string(hi_closed ? "" : "finite and ") + (lo_closed ? ">= " : "> ") + bound(lo, lo_name);
  else if (lo_inf)
    t = std::string(lo_closed ? "" : "finite and ") + (hi_closed ? "<= " : "< ") + bound(hi, hi_name);
  else
    t = std::string("in ") + (lo_closed ? "[" : "(") + bound(lo, lo_name) + ", " + bound(hi, hi_name) +
        (hi_closed ? "]" : ")");
  if (with_where && !where.empty()) t += " with " + where;
  if (!note.empty()) t += " (" + note + ")";
  return t;
}

std::span<const ParameterRow> parameter_table() { return kTable; }

const ParameterRow& parameter_row(SceneParameter q) { return kTable[static_cast<std::size_t>(q)]; }

std::string to_string(SceneParameter q) { return parameter_row(q).name; }

std::string parameter_label(SceneParameter q) {
  const ParameterRow& r = parameter_row(q);
  return r.scale == AxisScale::log ? "ln " + std::string(parameter_row(r.of).name) : r.name;
}

SceneParameter moved_parameter(SceneParameter q) {
  const ParameterRow& r = parameter_row(q);
  return r.scale == AxisScale::log ? moved_parameter(r.of) : r.moves;
}

bool moves_stored(std::span<const SceneParameter> free, SceneParameter stored) {
  for (SceneParameter q : free) {
    // A composite moves the one input it is set through; a row that moves itself moves all its inputs with
    // it (shear_rate: B and C on the cell's line).
    const ParameterRow& r = parameter_row(q);
    if (r.scale == AxisScale::log) {
      const SceneParameter base[] = {r.of};
      if (moves_stored(base, stored)) return true;
    } else if (r.moves != r.id ? r.moves == stored : (r.inputs & bit(stored)) != 0) {
      return true;
    }
  }
  return false;
}

std::vector<SceneParameter> stored_parameters(std::string_view table) {
  std::vector<SceneParameter> out;
  for (const ParameterRow& r : kTable)
    if (r.table && table == r.table) out.push_back(r.id);
  return out;
}

std::vector<SceneParameter> composite_parameters() {
  std::vector<SceneParameter> out;
  for (const ParameterRow& r : kTable)
    if (r.definition) out.push_back(r.id);
  return out;
}

bool usable_as(SceneParameter q, ParameterUse use) {
  const ParameterRow& r = parameter_row(q);
  switch (use) {
    case ParameterUse::scene_key:
      return r.table != nullptr;
    case ParameterUse::continuation:
      return r.continuation;
    case ParameterUse::axis:
      return r.axis;
  }
  return false;
}

bool is_material(SceneParameter q) {
  for (const ParameterRow& r : kTable)
    if ((parameter_row(q).inputs & bit(r.id)) && (!r.table || std::string_view(r.table) != "parameters")) return false;
  return true;
}

std::vector<std::string> parameter_names(ParameterUse use) {
  std::vector<std::string> names;
  for (const ParameterRow& r : kTable)
    if (usable_as(r.id, use)) names.emplace_back(r.name);
  return names;
}

SceneParameter parameter_from_string(std::string_view name, ParameterUse use) {
  for (const ParameterRow& r : kTable)
    if (name == r.name && usable_as(r.id, use)) return r.id;
  std::string list;
  for (const std::string& n : parameter_names(use)) list += (list.empty() ? "" : ", ") + n;
  const UseWords w = words(use);
  throw InvalidArgument(
      w.name, std::string(w.name) + " = '" + std::string(name) + "' is not a " + w.noun + ": must be one of " + list);
}

double get_parameter(const Scene& s, SceneParameter q) {
  const ParameterRow& r = parameter_row(q);
  return r.scale == AxisScale::log ? std::log(get_parameter(s, r.of)) : r.get(s);
}

void set_parameter(Scene& s, SceneParameter q, double value) {
  const ParameterRow& r = parameter_row(q);
  if (r.scale == AxisScale::log)
    set_parameter(s, r.of, std::exp(value));
  else
    r.set(s, value);
}

Domain parameter_domain(SceneParameter q, const Parameters& p) {
  const ParameterRow& r = parameter_row(q);
  return r.scale == AxisScale::log ? log_of(parameter_domain(r.of, p)) : r.domain(p);
}

Domain continuation_domain(SceneParameter q, const Parameters& p) { return parameter_domain(q, p); }

void require_in(SceneParameter q, const Domain& domain, double value) {
  if (domain.contains(value)) return;
  // An infinite value says what it is not, also where the domain's text names only its bounds ("in [0, pi]").
  std::string range = domain.text();
  if (std::isinf(value) && range.find("finite") == std::string::npos) range = "finite and " + range;
  require(false, parameter_row(q).name, value, range);
}

void validate_table(const Scene& s, std::string_view table) {
  for (const ParameterRow& r : kTable)
    if (r.table && table == r.table) require_in(r.id, parameter_domain(r.id, s.parameters), r.get(s));
}

bool independent(SceneParameter a, SceneParameter b) {
  // shear_rate scales B and C by one factor, so alpha = B/C stays; setting alpha (through B) leaves the cell's
  // shear rate. They share inputs but neither moves the other.
  const bool ratio_kept = (a == P::shear_rate && b == P::alpha) || (a == P::alpha && b == P::shear_rate);
  return a != b && (ratio_kept || (parameter_row(a).inputs & parameter_row(b).inputs) == 0);
}

const PhysicalCell& physical_cell(const Scene& s, const std::string& name) {
  const std::string needs = name +
                            " needs a physical scene: a [physical] table with shear_rate, viscosity, radius (or area "
                            "and volume), bending_modulus and shear_modulus, or their flags --shear-rate, --viscosity, "
                            "--radius (or --area with --volume), --bending-modulus, --shear-modulus";
  if (!s.physical) throw InvalidArgument(name, needs + " (this scene has none)");
  try {
    s.physical->validate_complete();
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(name, needs + " (" + e.what() + ")");
  }
  return *s.physical;
}

void require_usable(SceneParameter q, const Scene& s) {
  const ParameterRow& r = parameter_row(q);
  if (r.inputs & bit(P::shear_rate)) (void)physical_cell(s, r.name);
}

std::string nonfinite_reason(const Parameters& p) {
  // Beyond sqrt(DBL_MAX) ~ 1.3e154 a product of two such inputs overflows; 1e150 leaves room for the factors.
  // A tiny nonzero input (B = 1e-300) overflows the same way through its inverse.
  constexpr double huge = 1e150, tiny = 1 / huge;
  Scene s;
  s.parameters = p;
  std::string culprits;
  for (const ParameterRow& r : parameter_table()) {
    if (!is_material(r.id) || r.scale != AxisScale::linear || r.table == nullptr) continue;
    const double v = get_parameter(s, r.id);
    if (std::isfinite(v) && std::abs(v) <= huge && (v == 0 || std::abs(v) >= tiny)) continue;
    culprits += (culprits.empty() ? "" : ", ") + std::string(r.name) + " = " + format_value(v);
  }
  if (culprits.empty()) return "not finite: the computation overflowed or was undefined at these parameters";
  if (culprits == "C = inf") return "not finite: C = inf (the vesicle limit)";
  return "not finite: overflow from " + culprits;
}

std::string S_reason(const Parameters& p) {
  if (p.Delta0 == 0) return "S = inf: Delta0 = 0 (the vesicle limit)";
  if (!std::isfinite(p.C)) return "S = inf: C = inf (the vesicle limit)";
  return nonfinite_reason(p);
}

}  // namespace rbcstab
