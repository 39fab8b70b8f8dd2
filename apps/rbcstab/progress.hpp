#pragma once
// Progress on stderr for the commands that can run long (simulate and its relatives, report, continue, trace,
// diagram, bench): shown when stderr is a terminal or --progress is given, never with --quiet, and at most one
// line a second, so a short run prints nothing and a log or a pipe stays clean unless asked.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "rbcstab/core/progress.hpp"

namespace rbcstab::cli {

// "4.2s", "3m07s", "1h05m".
inline std::string duration(double s) {
  std::ostringstream ss;
  if (s >= 3600) ss << int(s / 3600) << "h" << std::setw(2) << std::setfill('0') << int(s / 60) % 60 << "m";
  else if (s >= 60) ss << int(s / 60) << "m" << std::setw(2) << std::setfill('0') << int(s) % 60 << "s";
  else ss << std::fixed << std::setprecision(1) << s << "s";
  return ss.str();
}

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

  // "rbcstab: <what> <done> of <total> <unit> (p%), elapsed e, ETA r"; total 0: "<what> <done> <unit>, elapsed e".
  // Empty when not enabled (the computation then skips its calls).
  ProgressCallback callback(const std::string& what, const std::string& unit) const {
    if (!enabled()) return {};
    using Clock = std::chrono::steady_clock;
    struct State {
      Clock::time_point start = Clock::now(), last = start;
    };
    auto state = std::make_shared<State>();
    return [state, what, unit](double done, double total) {
      const Clock::time_point now = Clock::now();
      if (now - state->last < std::chrono::seconds(1)) return;
      state->last = now;
      const double elapsed = std::chrono::duration<double>(now - state->start).count();
      std::ostringstream line;
      line << std::setprecision(6) << "rbcstab: " << what << " " << done;
      if (total > 0) line << " of " << total;
      if (!unit.empty()) line << " " << unit;
      if (total > 0) line << " (" << std::fixed << std::setprecision(0) << 100 * done / total << "%)";
      line << ", elapsed " << duration(elapsed);
      if (total > 0 && done > 0) line << ", ETA " << duration(elapsed * (total - done) / done);
      std::cerr << line.str() << "\n";
    };
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
