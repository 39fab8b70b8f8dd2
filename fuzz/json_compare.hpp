#pragma once
// "Every value a reader keeps is the value the file gave": a document written back from what was read, compared
// with the document that was read.
#include <nlohmann/json.hpp>
#include <set>
#include <string>

namespace rbcstab::fuzz {

// A path with its array indices dropped ("branch[3].x[1]" -> "branch[].x[]").
inline std::string pattern_of(const std::string& path) {
  std::string out;
  bool in_index = false;
  for (char c : path) {
    if (c == '[')
      in_index = true, out += "[]";
    else if (c == ']')
      in_index = false;
    else if (!in_index)
      out += c;
  }
  return out;
}

// "<key>_reason" beside a null "<key>": the writer's explanation of the null (explain_nulls, io/json.hpp), which
// no reader takes back.
inline bool explains_null(const nlohmann::json& object, const std::string& key) {
  const std::string suffix = "_reason";
  if (key.size() <= suffix.size() || key.compare(key.size() - suffix.size(), suffix.size(), suffix) != 0) return false;
  const auto it = object.find(key.substr(0, key.size() - suffix.size()));
  return it != object.end() && it->is_null();
}

// The path of the first value of `written` that `given` does not hold at the same place ("" if none): objects
// compare by the keys of `written`, arrays element by element and by length, numbers by value (1 == 1.0). The
// values a writer derives and a reader ignores are skipped: `derived` holds their paths without array indices
// ("curve.start"), or ".key" for the key at any depth.
inline std::string first_difference(const nlohmann::json& written, const nlohmann::json& given,
                                    const std::set<std::string>& derived = {}, const std::string& path = "") {
  if (written.is_object()) {
    if (!given.is_object()) return path.empty() ? "(the document)" : path;
    for (const auto& [key, value] : written.items()) {
      const std::string at = path.empty() ? key : path + "." + key;
      if (derived.count(pattern_of(at)) || derived.count("." + key)) continue;
      if (explains_null(written, key)) continue;
      const auto it = given.find(key);
      if (it == given.end()) return at + " (missing in the input)";
      if (std::string d = first_difference(value, *it, derived, at); !d.empty()) return d;
    }
    return "";
  }
  if (written.is_array()) {
    if (!given.is_array() || given.size() != written.size()) return path + " (length)";
    for (std::size_t k = 0; k < written.size(); ++k)
      if (std::string d = first_difference(written[k], given[k], derived, path + "[" + std::to_string(k) + "]");
          !d.empty())
        return d;
    return "";
  }
  return written == given ? "" : path + " = " + given.dump() + " read as " + written.dump();
}

}  // namespace rbcstab::fuzz
