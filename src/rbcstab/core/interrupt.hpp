#pragma once
// Ctrl-C for the long computations that take a stop flag (DiagramOptions::stop, PanelOptions::stop,
// PaperOptions::stop): while a StopOnSignal lives, SIGINT and SIGTERM set its flag instead of ending the process,
// so that a diagram leaves its journal resumable and a report or paper writes nothing half done. The handlers in
// place before are restored when it goes. A signal handler reaches only globals: every StopOnSignal shares one
// flag, so one at a time.
#include <atomic>
#include <csignal>

namespace rbcstab {

class StopOnSignal {
 public:
  StopOnSignal();  // clears the flag and installs the handlers
  ~StopOnSignal();
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;

  // What the computation's `stop` points to.
  const std::atomic<bool>* flag() const;

 private:
  struct sigaction previous_int_ {
  }, previous_term_{};
};

}  // namespace rbcstab
