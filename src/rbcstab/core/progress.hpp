#pragma once
// Progress of a long computation as it goes: `done` of `total` in the computation's own unit (time t of T,
// branch points, criterion evaluations, runs); total 0 when not known in advance. Called often (every
// integration step): the receiver throttles what it shows. An empty callback costs nothing.
// The text of a progress line and the throttle are here, once, for every front end (the command line's lines,
// the Python module's polls).
#include <chrono>
#include <functional>
#include <string>

namespace rbcstab {

using ProgressCallback = std::function<void(double done, double total)>;

// True at most once per interval: for what is called at every step but must act rarely (a progress line, a poll
// of Python's signal handlers). The first interval is waited out unless due_at_once.
class Throttle {
 public:
  explicit Throttle(double interval_seconds, bool due_at_once = false);
  bool due();              // an interval has passed since the last time it was due (then it restarts)
  double elapsed() const;  // seconds since construction

 private:
  using Clock = std::chrono::steady_clock;
  Clock::duration interval_;
  Clock::time_point start_, last_;
};

// "4.2s", "3m07s", "1h05m".
std::string duration_text(double seconds);
// "<what> <done> of <total> <unit> (p%), elapsed e, ETA r"; total 0: "<what> <done> <unit>, elapsed e".
std::string progress_text(const std::string& what, const std::string& unit, double done, double total, double elapsed);
// A callback that gives `line` the progress_text at most once per interval (nothing in the first: a short run
// shows nothing).
ProgressCallback progress_lines(const std::string& what, const std::string& unit,
                                std::function<void(const std::string&)> line, double interval_seconds = 1.0);

}  // namespace rbcstab
