#include "rbcstab/model/parameter_table.hpp"

#include <array>
#include <numbers>

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

// One row per SceneParameter, in its order (tests/model/parameter_table_test.cpp checks it).
const std::array<ParameterRow, 13> kTable{{
    {P::lambda, "lambda", "\\lambda", "", "viscosity ratio eta_in/eta_ex", "parameters", AxisScale::linear, P::lambda,
     P::lambda, bit(P::lambda), true, true, [](const Parameters&) { return open_above(0, true); },
     [](const Scene& s) { return s.parameters.lambda; }, [](Scene& s, double v) { s.parameters.lambda = v; }},
    {P::Delta, "Delta", "\\Delta", "", "excess area of the current shape", "parameters", AxisScale::linear, P::Delta,
     P::Delta, bit(P::Delta), true, true,
     [](const Parameters&) { return Domain{0, 4 * std::numbers::pi, false, false, "", "4 pi", "", ""}; },
     [](const Scene& s) { return s.parameters.Delta; }, [](Scene& s, double v) { s.parameters.Delta = v; }},
    {P::Delta0, "Delta0", "\\Delta_0", "", "excess area of the stress-free shape (0: the vesicle limit)", "parameters",
     AxisScale::linear, P::Delta0, P::Delta0, bit(P::Delta0), true, true, up_to_Delta,
     [](const Scene& s) { return s.parameters.Delta0; }, [](Scene& s, double v) { s.parameters.Delta0 = v; }},
    {P::B, "B", "\\mathcal{B}", "", "bending number eta gamma R^3 / kappa", "parameters", AxisScale::linear, P::B, P::B,
     bit(P::B), true, false, [](const Parameters&) { return open_above(0, false); },
     [](const Scene& s) { return s.parameters.B; }, [](Scene& s, double v) { s.parameters.B = v; }},
    {P::C, "C", "\\mathcal{C}", "", "capillary number eta gamma R / mu", "parameters", AxisScale::linear, P::C, P::C,
     bit(P::C), true, false,
     [](const Parameters&) { return Domain{0, kInf, false, true, "", "", "", "inf allowed: the vesicle limit"}; },
     [](const Scene& s) { return s.parameters.C; }, [](Scene& s, double v) { s.parameters.C = v; }},
    // The composites of the reduced system (Eq. Lambda_S) each move one input, so they move alone: Lambda
    // ~ sqrt(Delta) at fixed lambda (S unchanged), S ~ C at fixed Delta0 (Lambda unchanged).
    {P::Lambda, "Lambda", "\\Lambda", "", "sqrt(Delta)(23 lambda + 32)/(8 sqrt(30 pi)) of the reduced system, set through Delta",
     nullptr, AxisScale::linear, P::Lambda, P::Delta, bit(P::Delta) | bit(P::lambda), true, false,
     [](const Parameters&) { return open_above(0, false); },
     [](const Scene& s) { return s.parameters.Lambda(); },
     [](Scene& s, double v) {
       const double ratio = v / s.parameters.Lambda();
       s.parameters.Delta *= ratio * ratio;
     }},
    {P::S, "S", "S", "", "C sqrt(15 pi/(2 Delta0)) of the reduced system, set through C", nullptr, AxisScale::linear, P::S,
     P::C, bit(P::C) | bit(P::Delta0), true, false, [](const Parameters&) { return open_above(0, false); },
     [](const Scene& s) { return s.parameters.S(); },
     [](Scene& s, double v) {
       const double S = s.parameters.S();
       require(std::isfinite(S), "S", v, "continuable only from a finite S (Delta0 > 0 and C finite)");
       s.parameters.C *= v / S;
     }},
    {P::alpha, "alpha", "\\alpha", "", "B/C = mu R^2/kappa, set through B", nullptr, AxisScale::linear, P::alpha, P::B,
     bit(P::B) | bit(P::C), false, true, [](const Parameters&) { return open_above(0, false); },
     [](const Scene& s) { return s.parameters.alpha(); }, [](Scene& s, double v) { s.parameters.B = v * s.parameters.C; }},
    {P::lnB, "lnB", "\\ln \\mathcal{B}", "", "ln B, a log axis of the bending number", nullptr, AxisScale::log, P::B, P::B,
     bit(P::B), false, true, nullptr, nullptr, nullptr},
    {P::lnC, "lnC", "\\ln \\mathcal{C}", "", "ln C, a log axis of the capillary number", nullptr, AxisScale::log, P::C, P::C,
     bit(P::C), false, true, nullptr, nullptr, nullptr},
    {P::beta, "beta", "\\beta", "",
     "rotation of the axisymmetric shapes about y (pi/2 = 1.5707963267948966)", "initial",
     AxisScale::linear, P::beta, P::beta, bit(P::beta), true, true,
     [](const Parameters&) {
       return Domain{0, std::numbers::pi, true, true, "", "pi", "", "0: rest shape out of plane, pi/2: in plane"};
     },
     [](const Scene& s) { return s.beta; }, [](Scene& s, double v) { s.beta = v; }},
    {P::delta, "delta", "\\delta", "", "perturbation Delta_l(0) put in f_{l,0} for every l = 3..L", "initial",
     AxisScale::linear, P::delta, P::delta, bit(P::delta), false, false, up_to_Delta,
     [](const Scene& s) { return s.delta; }, [](Scene& s, double v) { s.delta = v; }},
    // Stored in the physical cell, whose table ([physical], io/scene_file.hpp) declares its key and flag
    // (--shear-rate) with the cell's other quantities from this row's name, description and domain.
    {P::shear_rate, "shear_rate", "\\dot\\gamma", "1/s",
     "shear rate gamma [1/s]; B and C follow at fixed alpha (a physical scene; time unit 1/gamma)", nullptr,
     AxisScale::geometric, P::shear_rate, P::shear_rate, bit(P::shear_rate) | bit(P::B) | bit(P::C), true, true,
     [](const Parameters&) { return Domain{0, kInf, false, false, "", "", "", "1/s"}; }, get_shear_rate,
     set_shear_rate},
}};

// A log row's domain: its base's, mapped by ln (ln 0 = -inf).
Domain log_of(const Domain& d) {
  auto name = [](const std::string& n) { return n.empty() ? n : "ln(" + n + ")"; };
  return Domain{std::log(d.lo), std::log(d.hi), d.lo_closed, d.hi_closed, name(d.lo_name), name(d.hi_name), d.where,
                d.note};
}

// How a message names a value of this use ("parameter = 'x'") and what it is not ("a continuation parameter").
struct UseWords {
  const char* name;
  const char* noun;
};
UseWords words(ParameterUse use) {
  switch (use) {
    case ParameterUse::scene_key: return {"key", "scene parameter"};
    case ParameterUse::continuation: return {"parameter", "continuation parameter"};
    case ParameterUse::axis: return {"axis", "diagram axis"};
  }
  return {"parameter", "parameter"};
}
}  // namespace

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

bool usable_as(SceneParameter q, ParameterUse use) {
  const ParameterRow& r = parameter_row(q);
  switch (use) {
    case ParameterUse::scene_key: return r.table != nullptr;
    case ParameterUse::continuation: return r.continuation;
    case ParameterUse::axis: return r.axis;
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
  throw InvalidArgument(w.name, std::string(w.name) + " = '" + std::string(name) + "' is not a " + w.noun +
                                    ": must be one of " + list);
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

}  // namespace rbcstab
