// The normal form's data: coefficient look-up and its one-line text.
#include "rbcstab/continuation/normal_form.hpp"

#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/json.hpp"

namespace rbcstab {

double NormalForm::coefficient(const std::string& name) const {
  for (const auto& [n, v] : coefficients)
    if (n == name) return v;
  return std::numeric_limits<double>::quiet_NaN();
}

nlohmann::json to_json(const NormalForm& nf) {
  nlohmann::json c = nlohmann::json::object();
  for (const auto& [n, v] : nf.coefficients) c[n] = number_or_null(v);
  return {{"kind", to_string(nf.kind)},
          {"criticality", to_string(nf.criticality)},
          {"coefficients", c},
          {"amplitude", number_or_null(nf.amplitude)},
          {"exponent", number_or_null(nf.exponent)},
          {"side", number_or_null(nf.side)},
          {"note", nf.note}};
}

NormalForm normal_form_from_json(const nlohmann::json& j) {
  auto fail = [](const std::string& what) { throw InvalidArgument("normal_form", "normal_form: " + what); };
  if (!j.is_object()) fail("not an object");
  auto string = [&](const char* key) {
    if (!j.contains(key) || !j.at(key).is_string()) fail(std::string("\"") + key + "\" must be a string");
    return j.at(key).get<std::string>();
  };
  auto number = [&](const nlohmann::json& v, const std::string& key) {
    if (v.is_null()) return std::numeric_limits<double>::quiet_NaN();
    if (!v.is_number()) fail("\"" + key + "\" must be a number or null");
    return v.get<double>();
  };
  NormalForm nf;
  nf.kind = from_string<NormalFormKind>(string("kind"), "normal_form.kind");
  nf.criticality = from_string<Criticality>(string("criticality"), "normal_form.criticality");
  nf.note = string("note");
  if (!j.contains("coefficients") || !j.at("coefficients").is_object()) fail("\"coefficients\" must be an object");
  for (const auto& [k, v] : j.at("coefficients").items()) nf.coefficients.emplace_back(k, number(v, k));
  for (const auto& [key, field] :
       {std::pair{"amplitude", &nf.amplitude}, std::pair{"exponent", &nf.exponent}, std::pair{"side", &nf.side}}) {
    if (!j.contains(key)) fail(std::string("\"") + key + "\" is missing");
    *field = number(j.at(key), key);
  }
  return nf;
}

namespace {

// Four significant digits: the coefficients are difference quotients accurate to ~1e-6 (multilinear.hpp).
std::string short_number(double v) {
  std::ostringstream os;
  os << std::setprecision(4) << v;
  return os.str();
}

}  // namespace

std::string to_text(const NormalForm& nf, const std::string& parameter) {
  std::string t = to_string(nf.kind);
  // A note that says "degenerate (k pairs)" already names the criticality.
  const bool named = nf.note.rfind(to_string(nf.criticality), 0) == 0;
  if (nf.criticality != Criticality::not_applicable && !named) t += ", " + to_string(nf.criticality);
  // The coefficient that decides: l1 (Hopf), c (period doubling), d (Neimark-Sacker), p2 (pitchfork, folds), none
  // (transcritical).
  const char* key = nf.kind == NormalFormKind::hopf              ? "l1"
                    : nf.kind == NormalFormKind::period_doubling ? "c"
                    : nf.kind == NormalFormKind::neimark_sacker  ? "d"
                                                                 : "p2";
  if (nf.kind != NormalFormKind::transcritical && !std::isnan(nf.coefficient(key)))
    t += std::string(" (") + key + " = " + short_number(nf.coefficient(key)) + ")";
  if (!nf.note.empty()) t += ": " + nf.note;
  if (std::isfinite(nf.amplitude)) {
    const std::string& P = parameter;
    const char* what = nf.kind == NormalFormKind::hopf              ? ", orbit"
                       : nf.kind == NormalFormKind::period_doubling ? ", doubled orbit"
                       : nf.kind == NormalFormKind::neimark_sacker  ? ", invariant circle"
                                                                    : ",";
    t += std::string(what) + " |x - x*| ~ " + short_number(nf.amplitude) + " |" + P + " - " + P + "*|" +
         (nf.exponent == 0.5 ? "^(1/2)" : "");
    if (nf.side > 0) t += " for " + P + " > " + P + "*";
    if (nf.side < 0) t += " for " + P + " < " + P + "*";
  }
  return t;
}

}  // namespace rbcstab
