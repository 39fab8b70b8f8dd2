#include "rbcstab/core/enum_table.hpp"

#include "rbcstab/core/error.hpp"

namespace rbcstab {

void throw_not_one_of(std::string_view key, std::string_view name, const std::vector<std::string>& allowed) {
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
  throw InvalidArgument(std::string(key), std::string(key) + " = '" + std::string(name) + "' is not one of: " + list);
}

}  // namespace rbcstab
