#pragma once
// Writing outputs that appear whole or not at all: hidden sibling names for staging files and folders,
// and the end of a plotting log for error messages.
#include <cstddef>
#include <filesystem>
#include <string>

#include "rbcstab/io/files.hpp"
#include "rbcstab/report/report.hpp"

namespace rbcstab::detail {

// ".<name of target><tag><pid>-<random hex>" (io staging_prefix), created beside target and renamed onto it;
// the pid lets a later run remove the staging of a killed one (remove_stale_staging).
std::string hidden_sibling_name(const std::filesystem::path& target, const char* tag);

// The last n characters of the file at path ("..." in front when cut; "" when unreadable).
std::string log_tail(const std::string& path, std::size_t n);

// The folder an output path names, checked before anything is computed: an existing one without overwrite is
// refused (InvalidArgument("output")), a missing parent is a ReportError.
std::filesystem::path output_target(const std::string& output, bool overwrite);

// Renames the finished folder tmp onto target; an existing target (overwrite) is swapped out whole, then removed.
void publish_folder(const std::filesystem::path& tmp, const std::filesystem::path& target);

// Runs body(tmp) on a fresh hidden sibling folder of target (body publishes it by renaming); on any
// failure the folder is removed, so nothing half-written is left behind.
template <class Body>
void in_staging_folder(const std::filesystem::path& target, Body&& body) {
  std::error_code ec;
  for (const char* tag : {".tmp-", ".old-"})
    rbcstab::remove_stale_staging(target.parent_path().string(), target.filename().string(), tag);
  const std::filesystem::path tmp = target.parent_path() / hidden_sibling_name(target, ".tmp-");
  std::filesystem::create_directory(tmp, ec);
  if (ec) throw rbcstab::ReportError("output: cannot create " + tmp.string() + ": " + ec.message());
  try {
    body(tmp);
  } catch (const std::filesystem::filesystem_error& e) {
    std::filesystem::remove_all(tmp, ec);
    throw rbcstab::ReportError(std::string("output: ") + e.what());
  } catch (...) {
    std::filesystem::remove_all(tmp, ec);
    throw;
  }
}

}  // namespace rbcstab::detail
