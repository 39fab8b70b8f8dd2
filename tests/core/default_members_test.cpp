// Result structs are fully initialised by default construction: every scalar member has a default
// member initialiser. Each struct is default-initialised (not value-initialised) over storage filled
// with a byte pattern, so a member without an initialiser would show the pattern (0x65: bool 101).
#include <gtest/gtest.h>

#include <cstring>
#include <new>

#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/integrate/work_precision.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {
namespace {

template <class T, class Check>
void on_dirty_storage(Check check) {
  alignas(T) unsigned char storage[sizeof(T)];
  std::memset(storage, 0x65, sizeof storage);
  T* t = new (storage) T;  // default-initialisation: only the default member initialisers run
  check(*t);
  t->~T();
}

TEST(DefaultMembers, LevelChoice) {
  on_dirty_storage<LevelChoice>([](const LevelChoice& c) {
    EXPECT_EQ(c.level, ModelLevel::automatic);
    EXPECT_FALSE(c.exact);
    EXPECT_TRUE(c.reason.empty());
  });
}

TEST(DefaultMembers, SimulationResultAndItsMove) {
  on_dirty_storage<SimulationResult>([](SimulationResult& r) {
    EXPECT_EQ(r.level.level, ModelLevel::automatic);
    EXPECT_FALSE(r.level.exact);
    EXPECT_EQ(r.status, IntegrationStatus::success);
    EXPECT_FALSE(r.oscillating);
    const SimulationResult moved = std::move(r);  // an unused result moved out (report --no-reduced)
    EXPECT_FALSE(moved.level.exact);
  });
}

TEST(DefaultMembers, WorkPrecisionRow) {
  on_dirty_storage<WorkPrecisionRow>([](const WorkPrecisionRow& w) {
    EXPECT_EQ(w.level, ModelLevel::automatic);
    EXPECT_EQ(w.stepper, Stepper::rk8pd);
    EXPECT_EQ(w.status, IntegrationStatus::success);
    EXPECT_EQ(w.rtol, 0);
    EXPECT_EQ(w.rhs_evaluations + w.jacobian_evaluations + w.steps, 0u);
    EXPECT_EQ(w.seconds + w.error_Delta + w.error_sigma, 0);
    EXPECT_EQ(w.l_Delta, 2);
    EXPECT_FALSE(w.verdict_changed);
  });
}

}  // namespace
}  // namespace rbcstab
