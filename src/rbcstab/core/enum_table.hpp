#pragma once
// Enum <-> name from one table per enum. Next to an enum E its header specialises
//
//   template <> struct EnumTable<E> {
//     static constexpr EnumName<E> entries[] = {{E::a, "a"}, {E::b, "b"}};
//   };
//
// listing every value under its canonical name (what outputs write and input accepts). A value may
// appear again further down under an alias that input also accepts; outputs and the allowed-names
// list use the first name. to_string, from_string and enum_names follow from the table, so a name is
// spelled in exactly one place.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace rbcstab {

template <class E>
struct EnumName {
  E value;
  std::string_view name;
};

template <class E>
struct EnumTable;  // specialised next to each enum

template <class E>
concept TabledEnum = std::is_enum_v<E> && requires {
  EnumTable<E>::entries;
};

// Every name is distinct (else from_string would be ambiguous) and the values the table names are
// 0, 1, ..., n - 1 with none skipped (the enums here are contiguous from 0: a gap is a forgotten value).
template <TabledEnum E>
constexpr bool enum_table_is_valid() {
  const auto& t = EnumTable<E>::entries;
  const std::size_t size = std::size(t);
  std::size_t count = 0;  // distinct values = 1 + the largest value, if none is skipped
  for (std::size_t i = 0; i < size; ++i) {
    bool first = true;
    for (std::size_t j = 0; j < i; ++j) {
      if (t[j].name == t[i].name) return false;
      if (t[j].value == t[i].value) first = false;
    }
    if (first) ++count;
  }
  for (std::size_t i = 0; i < size; ++i)
    if (static_cast<std::size_t>(t[i].value) >= count) return false;
  return true;
}

// Canonical name of value; "?" only for a value outside the enum (e.g. memory never initialised).
template <TabledEnum E>
std::string to_string(E value) {
  static_assert(enum_table_is_valid<E>(), "EnumTable<E>: duplicate name or a value without a name");
  for (const auto& e : EnumTable<E>::entries)
    if (e.value == value) return std::string(e.name);
  return "?";
}

// The canonical names in table order (for error messages and CLI choices).
template <TabledEnum E>
const std::vector<std::string>& enum_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const auto& e : EnumTable<E>::entries)
      if (to_string(e.value) == e.name) v.emplace_back(e.name);
    return v;
  }();
  return names;
}

template <TabledEnum E>
std::optional<E> try_from_string(std::string_view name) {
  static_assert(enum_table_is_valid<E>(), "EnumTable<E>: duplicate name or a value without a name");
  for (const auto& e : EnumTable<E>::entries)
    if (e.name == name) return e.value;
  return std::nullopt;
}

// Throws InvalidArgument(key, "<key> = '<name>' is not one of: <allowed, comma-separated>").
[[noreturn]] void throw_not_one_of(std::string_view key, std::string_view name,
                                   const std::vector<std::string>& allowed);

// The value named name (canonical or alias); otherwise InvalidArgument naming key, name and the
// canonical names.
template <TabledEnum E>
E from_string(std::string_view name, std::string_view key) {
  if (const auto v = try_from_string<E>(name)) return *v;
  throw_not_one_of(key, name, enum_names<E>());
}

}  // namespace rbcstab
