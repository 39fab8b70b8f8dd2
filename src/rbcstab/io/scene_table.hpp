#pragma once
// One table of a scene file as plain values. The parser reads the TOML text once into these; the module that
// owns a table gives its keys their meaning (io: the scene's keys; sweep: [diagram]; report: [fig6e],
// [continuation]) through the typed reads below, which name the key ("diagram.counts") in every message.
#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <variant>
#include <vector>

namespace rbcstab {

class SceneTable {
 public:
  using Item = std::variant<bool, long long, double, std::string>;
  struct Value {
    enum class Shape { scalar, array, table };
    Shape shape = Shape::scalar;
    std::vector<Item> items;        // one item for a scalar
    std::vector<std::string> keys;  // Shape::table (an inline table such as { 3 = 1e-3 }): each item's key
  };

  SceneTable() = default;
  explicit SceneTable(std::string name) : name_(std::move(name)) {}

  const std::string& name() const { return name_; }  // "parameters", "diagram"; "" for the file's root
  std::string path(const std::string& key) const;    // "diagram.counts" ("name" at the root)
  void set(const std::string& key, Value value) { values_[key] = std::move(value); }
  bool has(const std::string& key) const { return values_.count(key) > 0; }
  const std::map<std::string, Value>& values() const { return values_; }

  // Throws InvalidArgument(path(key), "unknown scene key '<path>' (allowed here: a, b, ...)") for the first key
  // outside `allowed`.
  void allow_only(const std::set<std::string>& allowed) const;
  // Typed reads of a present key; another type throws InvalidArgument(path(key), "<path> must be <type>").
  double number(const std::string& key) const;  // an integer is accepted
  long long integer(const std::string& key) const;
  std::string text(const std::string& key) const;
  bool boolean(const std::string& key) const;  // true or false
  // Arrays of exactly `count` items (0: any non-empty number); otherwise "<path> must be <what>".
  std::vector<double> numbers(const std::string& key, std::size_t count, const std::string& what) const;
  std::vector<long long> integers(const std::string& key, std::size_t count, const std::string& what) const;
  std::vector<std::string> texts(const std::string& key, std::size_t count, const std::string& what) const;
  // An inline table of integer modes l to numbers, { 3 = 1e-3, 7 = 1e-12 }.
  std::map<int, double> modes(const std::string& key) const;

 private:
  const Value& at(const std::string& key) const;
  std::string name_;
  std::map<std::string, Value> values_;
};

}  // namespace rbcstab
