#include "rbcstab/io/scene_table.hpp"

#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {
const double* as_number(const SceneTable::Item& item, double& scratch) {
  if (const double* d = std::get_if<double>(&item)) return d;
  if (const long long* i = std::get_if<long long>(&item)) {
    scratch = double(*i);
    return &scratch;
  }
  return nullptr;
}

// An item as the file gave it, for messages ("abc" quoted, so that a string reads as one).
std::string shown(const SceneTable::Item& item) {
  if (const bool* b = std::get_if<bool>(&item)) return *b ? "true" : "false";
  if (const long long* i = std::get_if<long long>(&item)) return std::to_string(*i);
  if (const double* d = std::get_if<double>(&item)) {
    // As TOML wrote it: a float with an integral value keeps its ".0" (L = 3.0 is refused for being a float).
    const std::string text = format_value(*d);
    return text.find_first_of(".eEn") == std::string::npos ? text + ".0" : text;
  }
  return "\"" + std::get<std::string>(item) + "\"";
}
std::string shown(const SceneTable::Value& v) {
  using Shape = SceneTable::Value::Shape;
  if (v.shape == Shape::scalar) return shown(v.items[0]);
  std::string out;
  for (std::size_t k = 0; k < v.items.size(); ++k)
    out += (k ? ", " : "") + (v.shape == Shape::table ? v.keys[k] + " = " : "") + shown(v.items[k]);
  return v.shape == Shape::table ? "{ " + out + " }" : "[" + out + "]";
}

// The items of an array of `count` items (0: any non-empty) each convertible by `get`, or InvalidArgument.
template <class T, class Get>
std::vector<T> array_of(const SceneTable& t, const SceneTable::Value& v, const std::string& key, std::size_t count,
                        const std::string& what, Get get) {
  const std::string path = t.path(key);
  const bool size_ok = count == 0 ? !v.items.empty() : v.items.size() == count;
  if (v.shape != SceneTable::Value::Shape::array || !size_ok)
    throw InvalidArgument(path, path + " = " + shown(v) + " must be " + what);
  std::vector<T> out;
  for (const SceneTable::Item& item : v.items) {
    T x{};
    if (!get(item, x)) throw InvalidArgument(path, path + " = " + shown(v) + " must be " + what);
    out.push_back(x);
  }
  return out;
}
}  // namespace

std::string SceneTable::path(const std::string& key) const { return name_.empty() ? key : name_ + "." + key; }

const SceneTable::Value& SceneTable::at(const std::string& key) const {
  const auto it = values_.find(key);
  if (it == values_.end()) throw InvalidArgument(path(key), path(key) + " is missing");
  return it->second;
}

void SceneTable::allow_only(const std::set<std::string>& allowed) const {
  for (const auto& [key, value] : values_) {
    if (allowed.count(key)) continue;
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    throw InvalidArgument(path(key), "unknown scene key '" + path(key) + "' (allowed here: " + list + ")");
  }
}

double SceneTable::number(const std::string& key) const {
  const Value& v = at(key);
  double scratch = 0;
  const double* d = v.shape == Value::Shape::scalar ? as_number(v.items[0], scratch) : nullptr;
  if (!d) throw InvalidArgument(path(key), path(key) + " = " + shown(v) + " must be a number");
  return *d;
}

long long SceneTable::integer(const std::string& key) const {
  const Value& v = at(key);
  const long long* i = v.shape == Value::Shape::scalar ? std::get_if<long long>(&v.items[0]) : nullptr;
  if (!i) throw InvalidArgument(path(key), path(key) + " = " + shown(v) + " must be an integer");
  return *i;
}

std::string SceneTable::text(const std::string& key) const {
  const Value& v = at(key);
  const std::string* s = v.shape == Value::Shape::scalar ? std::get_if<std::string>(&v.items[0]) : nullptr;
  if (!s) throw InvalidArgument(path(key), path(key) + " = " + shown(v) + " must be a string");
  return *s;
}

bool SceneTable::boolean(const std::string& key) const {
  const Value& v = at(key);
  const bool* b = v.shape == Value::Shape::scalar ? std::get_if<bool>(&v.items[0]) : nullptr;
  if (!b) throw InvalidArgument(path(key), path(key) + " = " + shown(v) + " must be true or false");
  return *b;
}

std::vector<double> SceneTable::numbers(const std::string& key, std::size_t count, const std::string& what) const {
  return array_of<double>(*this, at(key), key, count, what, [](const Item& item, double& x) {
    double scratch = 0;
    const double* d = as_number(item, scratch);
    if (d) x = *d;
    return d != nullptr;
  });
}

std::vector<long long> SceneTable::integers(const std::string& key, std::size_t count, const std::string& what) const {
  return array_of<long long>(*this, at(key), key, count, what, [](const Item& item, long long& x) {
    const long long* i = std::get_if<long long>(&item);
    if (i) x = *i;
    return i != nullptr;
  });
}

std::vector<std::string> SceneTable::texts(const std::string& key, std::size_t count, const std::string& what) const {
  return array_of<std::string>(*this, at(key), key, count, what, [](const Item& item, std::string& x) {
    const std::string* s = std::get_if<std::string>(&item);
    if (s) x = *s;
    return s != nullptr;
  });
}

std::map<int, double> SceneTable::modes(const std::string& key) const {
  const Value& v = at(key);
  const std::string p = path(key);
  if (v.shape != Value::Shape::table)
    throw InvalidArgument(p, p + " = " + shown(v) + " must be a table of mode = value, e.g. { 3 = 1e-3 }");
  std::map<int, double> out;
  std::map<int, std::string> key_of;  // the key that gave each mode: "3" and "03" name one mode
  for (std::size_t k = 0; k < v.items.size(); ++k) {
    const std::string& ks = v.keys[k];
    int l = 0;
    try {
      std::size_t pos = 0;
      l = std::stoi(ks, &pos);
      if (pos != ks.size()) throw std::invalid_argument(ks);
    } catch (const std::exception&) {
      throw InvalidArgument(p, p + " has key '" + ks + "': keys must be integer modes l >= 3");
    }
    double scratch = 0;
    const double* d = as_number(v.items[k], scratch);
    if (!d) throw InvalidArgument(p + "." + ks, p + "." + ks + " = " + shown(v.items[k]) + " must be a number");
    if (const auto [it, fresh] = key_of.emplace(l, ks); !fresh)
      throw InvalidArgument(p, p + " has keys '" + it->second + "' and '" + ks + "' for mode l = " + std::to_string(l) +
                                   ": give each mode once");
    out[l] = *d;
  }
  return out;
}

}  // namespace rbcstab
