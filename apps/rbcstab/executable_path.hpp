#pragma once
// The running rbcstab binary's path: an installed tool finds its data (the plotting script) beside it.
#include <filesystem>
#include <string>

namespace rbcstab::cli {

inline std::string executable_path() {
  std::error_code ec;
  const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : p.string();
}

}  // namespace rbcstab::cli
