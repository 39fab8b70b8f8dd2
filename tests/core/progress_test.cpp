// The one progress and Ctrl-C facility of the long commands: the lines' text, the throttle, and the scoped
// SIGINT/SIGTERM catcher that restores the handlers it replaced.
#include <gtest/gtest.h>

#include <atomic>
#include <csignal>
#include <string>
#include <vector>

#include "rbcstab/core/interrupt.hpp"
#include "rbcstab/core/progress.hpp"

namespace rbcstab {
namespace {

TEST(Progress, DurationsReadAsAPersonWritesThem) {
  EXPECT_EQ(duration_text(4.21), "4.2s");
  EXPECT_EQ(duration_text(187), "3m07s");
  EXPECT_EQ(duration_text(3900), "1h05m");
}

TEST(Progress, ALineSaysDoneOfTotalElapsedAndEta) {
  EXPECT_EQ(progress_text("rbcstab: bench truncation:", "runs", 2, 8, 10),
            "rbcstab: bench truncation: 2 of 8 runs (25%), elapsed 10.0s, ETA 30.0s");
  EXPECT_EQ(progress_text("rbcstab: simulate: t =", "", 12.5, 0, 61), "rbcstab: simulate: t = 12.5, elapsed 1m01s");
}

TEST(Progress, TheThrottleWaitsOutItsInterval) {
  Throttle slow(3600), at_once(3600, true), always(0);
  EXPECT_FALSE(slow.due());
  EXPECT_TRUE(at_once.due());
  EXPECT_FALSE(at_once.due());
  EXPECT_TRUE(always.due());
  EXPECT_TRUE(always.due());
  // A callback of lines shows nothing in its first interval: a short run prints nothing.
  std::vector<std::string> lines;
  const ProgressCallback quiet = progress_lines(
      "w", "u", [&](const std::string& l) { lines.push_back(l); }, 3600);
  quiet(1, 2);
  EXPECT_TRUE(lines.empty());
  const ProgressCallback eager = progress_lines(
      "w", "u", [&](const std::string& l) { lines.push_back(l); }, 0);
  eager(1, 2);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].rfind("w 1 of 2 u (50%), elapsed ", 0), 0u);
}

std::atomic<int> g_previous_handler_calls{0};
extern "C" void previous_handler(int) { ++g_previous_handler_calls; }

TEST(Interrupt, SignalsSetTheFlagAndThePreviousHandlersComeBack) {
  std::signal(SIGINT, previous_handler);
  std::signal(SIGTERM, previous_handler);
  {
    const StopOnSignal stop;
    EXPECT_FALSE(stop.flag()->load());
    std::raise(SIGINT);
    EXPECT_TRUE(stop.flag()->load());
    EXPECT_EQ(g_previous_handler_calls.load(), 0);
  }
  {
    const StopOnSignal again;  // a new one starts cleared
    EXPECT_FALSE(again.flag()->load());
    std::raise(SIGTERM);
    EXPECT_TRUE(again.flag()->load());
  }
  std::raise(SIGINT);
  std::raise(SIGTERM);
  EXPECT_EQ(g_previous_handler_calls.load(), 2);
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

}  // namespace
}  // namespace rbcstab
