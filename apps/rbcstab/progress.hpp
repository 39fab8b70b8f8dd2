#pragma once
// Progress on stderr for the commands that can run long (simulate and its relatives, report, continue, trace,
// diagram, bench, paper): shown when stderr is a terminal or --progress is given, never with --quiet, and at most
// one line a second, so a short run prints nothing and a log or a pipe stays clean unless asked. The lines' text
// is the library's (core/progress.hpp, sweep/sweep_io.hpp progress_text), as is Ctrl-C (core/interrupt.hpp).
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <functional>
#include <iostream>
#include <string>

#include "rbcstab/core/interrupt.hpp"
#include "rbcstab/core/progress.hpp"
#include "rbcstab/sweep/sweep_io.hpp"

namespace rbcstab::cli {

class ProgressOutput {
 public:
  // --progress, and --quiet unless the command has its own flag (`quiet` then points to its value).
  void add_flags(CLI::App& app, const bool* quiet = nullptr) {
    app.add_flag("--progress", asked_, "show progress on stderr even when it is not a terminal (at most 1 line/s)");
    if (quiet) {
      quiet_ = quiet;
    } else {
      app.add_flag("--quiet", own_quiet_, "no progress on stderr");
      quiet_ = &own_quiet_;
    }
  }
  bool enabled() const { return !*quiet_ && (asked_ || isatty(STDERR_FILENO)); }

  // "rbcstab: <what> <done> of <total> <unit> ..." (progress_text); empty when not enabled (the computation then
  // skips its calls).
  ProgressCallback callback(const std::string& what, const std::string& unit) const {
    if (!enabled()) return {};
    return progress_lines("rbcstab: " + what, unit, [](const std::string& line) { std::cerr << line << "\n"; });
  }
  // A diagram's points after `lead` ("rbcstab: report: diagram 12/64, ..."); empty when not enabled.
  std::function<void(const Progress&)> grid(const std::string& lead, bool detail = false) const {
    if (!enabled()) return {};
    return [lead, detail](const Progress& p) { std::cerr << lead << progress_text(p, detail) << "\n"; };
  }
  // One line as a step starts.
  void step(const std::string& text) const {
    if (enabled()) std::cerr << "rbcstab: " << text << "\n";
  }

 private:
  bool asked_ = false, own_quiet_ = false;
  const bool* quiet_ = &own_quiet_;
};

}  // namespace rbcstab::cli
