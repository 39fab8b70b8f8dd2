#include "rbcstab/core/progress.hpp"

#include <iomanip>
#include <memory>
#include <sstream>

namespace rbcstab {

Throttle::Throttle(double interval_seconds, bool due_at_once)
    : interval_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(interval_seconds))),
      start_(Clock::now()),
      last_(due_at_once ? Clock::time_point{} : start_) {}

bool Throttle::due() {
  const Clock::time_point now = Clock::now();
  if (now - last_ < interval_) return false;
  last_ = now;
  return true;
}

double Throttle::elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

std::string duration_text(double s) {
  std::ostringstream ss;
  if (s >= 3600)
    ss << int(s / 3600) << "h" << std::setw(2) << std::setfill('0') << int(s / 60) % 60 << "m";
  else if (s >= 60)
    ss << int(s / 60) << "m" << std::setw(2) << std::setfill('0') << int(s) % 60 << "s";
  else
    ss << std::fixed << std::setprecision(1) << s << "s";
  return ss.str();
}

std::string progress_text(const std::string& what, const std::string& unit, double done, double total, double elapsed) {
  std::ostringstream line;
  line << std::setprecision(6) << what << " " << done;
  if (total > 0) line << " of " << total;
  if (!unit.empty()) line << " " << unit;
  if (total > 0) line << " (" << std::fixed << std::setprecision(0) << 100 * done / total << "%)";
  line << ", elapsed " << duration_text(elapsed);
  if (total > 0 && done > 0) line << ", ETA " << duration_text(elapsed * (total - done) / done);
  return line.str();
}

ProgressCallback progress_lines(const std::string& what, const std::string& unit,
                                std::function<void(const std::string&)> line, double interval_seconds) {
  auto throttle = std::make_shared<Throttle>(interval_seconds);
  return [throttle, what, unit, line = std::move(line)](double done, double total) {
    if (throttle->due()) line(progress_text(what, unit, done, total, throttle->elapsed()));
  };
}

}  // namespace rbcstab
