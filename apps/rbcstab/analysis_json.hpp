#pragma once
// JSON views of analysis results for the thresholds, post and summary commands: a quantity outside its domain
// is null with "<key>_reason" beside it, never silently missing.
#include <complex>
#include <iomanip>
#include <sstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rbcstab/analysis/quantity.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/verdict/predict.hpp"

namespace rbcstab::cli {

inline void put(nlohmann::json& j, const std::string& key, const Quantity& q) {
  j[key] = q.valid() ? number_or_null(q.value) : nlohmann::json(nullptr);
  if (!q.reason.empty()) j[key + "_reason"] = q.reason;
}

inline nlohmann::json to_json(const ModePrediction& m) {
  nlohmann::json j;
  j["unstable_modes"] = m.unstable;
  j["l_Delta"] = m.l_Delta;
  j["rate"] = by_mode(m.rate);
  j["status"] = to_string(m.status);
  if (!m.reason.empty()) j["reason"] = m.reason;
  return j;
}

inline nlohmann::json to_json(const std::complex<double>& z) { return {number_or_null(z.real()), number_or_null(z.imag())}; }

// A quantity for text output: its value, or "n/a (reason)" outside its domain.
inline std::string show(const Quantity& q) {
  std::ostringstream s;
  s << std::setprecision(6);
  if (q.valid())
    s << q.value;
  else
    s << "n/a (" << q.reason << ")";
  return s.str();
}

// "3, 4" or "none"
inline std::string mode_list(const std::vector<int>& modes) {
  if (modes.empty()) return "none";
  std::string s;
  for (std::size_t i = 0; i < modes.size(); ++i) s += (i ? ", " : "") + std::to_string(modes[i]);
  return s;
}

}  // namespace rbcstab::cli
