#include "rbcstab/core/interrupt.hpp"

namespace rbcstab {

namespace {
// Set from a signal handler: a lock-free atomic is the one object it may write.
std::atomic<bool> g_stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void request_stop(int) { g_stop_requested.store(true); }
}  // namespace

StopOnSignal::StopOnSignal() {
  g_stop_requested.store(false);
  struct sigaction action {};
  action.sa_handler = request_stop;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // as std::signal installs it: a blocking read or write is resumed, not failed
  sigaction(SIGINT, &action, &previous_int_);
  sigaction(SIGTERM, &action, &previous_term_);
}

StopOnSignal::~StopOnSignal() {
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
}

const std::atomic<bool>* StopOnSignal::flag() const { return &g_stop_requested; }

}  // namespace rbcstab
