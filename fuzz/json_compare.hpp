#pragma once
// "Every value a reader keeps is the value the file gave": a document written back from what was read, compared
// with the document that was read.
#include <nlohmann/json.hpp>
#include <set>
#include <string>

namespace rbcstab::fuzz {

// The path of the first value of `written` that `given` does not hold at the same place ("" if none): objects
// compare by the keys of `written` (a key the reader ignores is not compared; one in `derived` is skipped: the
// writer computes it), arrays element by element and by length, numbers by value (1 == 1.0).
inline std::string first_difference(const nlohmann::json& written, const nlohmann::json& given,
                                    const std::set<std::string>& derived = {}, const std::string& path = "") {
  if (written.is_object()) {
    if (!given.is_object()) return path.empty() ? "(the document)" : path;
    for (const auto& [key, value] : written.items()) {
      if (derived.count(key)) continue;
      const std::string at = path.empty() ? key : path + "." + key;
      const auto it = given.find(key);
      if (it == given.end()) return at + " (missing in the input)";
      if (std::string d = first_difference(value, *it, derived, at); !d.empty()) return d;
    }
    return "";
  }
  if (written.is_array()) {
    if (!given.is_array() || given.size() != written.size()) return path + " (length)";
    for (std::size_t k = 0; k < written.size(); ++k)
      if (std::string d = first_difference(written[k], given[k], derived, path + "[" + std::to_string(k) + "]"); !d.empty())
        return d;
    return "";
  }
  return written == given ? "" : path + " = " + given.dump() + " read as " + written.dump();
}

}  // namespace rbcstab::fuzz
