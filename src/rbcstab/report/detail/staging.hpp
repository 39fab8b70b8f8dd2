#pragma once
// Writing outputs that appear whole or not at all: hidden sibling names for staging files and folders,
// and the end of a plotting log for error messages.
#include <cstddef>
#include <filesystem>
#include <string>

namespace rbcstab::detail {

// ".<name of target><tag><pid>-<random hex>" (io staging_prefix), created beside target and renamed onto it;
// the pid lets a later run remove the staging of a killed one (remove_stale_staging).
std::string hidden_sibling_name(const std::filesystem::path& target, const char* tag);

// The last n characters of the file at path ("..." in front when cut; "" when unreadable).
std::string log_tail(const std::string& path, std::size_t n);

}  // namespace rbcstab::detail
