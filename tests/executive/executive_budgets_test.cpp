// The cyclic executive on virtual time, budgets met: every activation runs once, on the frame grid
// from the start, in table order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "executive_test_support.hpp"
#include "ringlet/executive/executive.hpp"

namespace ringlet::executive::test {
namespace {

TEST(ExecutiveBudgets, ThousandCleanFramesRunEveryActivationOnce) {
  Rig rig;
  auto& fast = rig.add(spec("fast", 1, 0, 2ms), 1ms);
  auto& third = rig.add(spec("third", 3, 1, 3ms), 2ms);
  auto& tenth = rig.add(spec("tenth", 10, 5, 1ms), 1ms);
  auto& exec = rig.build();

  EXPECT_EQ(exec.run(1000), StopReason::kFrameLimit);

  EXPECT_EQ(fast.frames(), frames_where(1000, 1, 0));
  EXPECT_EQ(third.frames(), frames_where(1000, 3, 1));
  EXPECT_EQ(tenth.frames(), frames_where(1000, 10, 5));
  const auto stats = exec.task_stats();
  EXPECT_EQ(stats[0].runs, 1000U);
  EXPECT_EQ(stats[1].runs, 333U);
  EXPECT_EQ(stats[2].runs, 100U);
  for (const auto& s : stats) {
    EXPECT_EQ(s.overruns, 0U);
    EXPECT_EQ(s.skipped, 0U);
    EXPECT_EQ(s.degraded_runs, 0U);
  }
  EXPECT_EQ(stats[1].wall.min(), 2ms);
  EXPECT_EQ(stats[1].wall.max(), 2ms);
  EXPECT_EQ(stats[1].cpu.max(), 2ms);

  const auto& f = exec.frame_stats();
  EXPECT_EQ(f.frames, 1000U);
  EXPECT_EQ(f.frame_overruns, 0U);
  EXPECT_EQ(f.slips, 0U);
  EXPECT_EQ(f.wake_latency.count(), 1000U);
  EXPECT_EQ(f.wake_latency.max(), Nanos{0});  // a virtual clock wakes exactly on time
  EXPECT_EQ(f.busy.max(), 4ms);               // frame 25: 1 + 2 + 1 ms
  EXPECT_EQ(exec.next_frame(), 1000U);
  EXPECT_EQ(exec.heartbeat().load(), 1000U);
  EXPECT_FALSE(exec.failsafe_triggered());
  EXPECT_EQ(exec.failsafe_task(), -1);
  EXPECT_FALSE(rig.actuators.in_safe_state());
  EXPECT_TRUE(rig.drain().empty());
  // Last frame 999 was due at start + 999 periods and ran only fast (1 ms).
  EXPECT_EQ(rig.clock.now(), due(999) + 1ms);
}

TEST(ExecutiveBudgets, FramesAreDueOnTheGridFromTheStart) {
  Rig rig;
  auto& t = rig.add(spec("t", 1, 0, 5ms), 3ms);
  rig.build().run(50);
  ASSERT_EQ(t.activations().size(), 50U);
  for (const auto& ctx : t.activations()) {
    EXPECT_EQ(ctx.frame_start, due(ctx.frame)) << "frame " << ctx.frame;
    EXPECT_EQ(ctx.now, due(ctx.frame)) << "frame " << ctx.frame;
  }
}

TEST(ExecutiveBudgets, OrderWithinAFrameIsTableOrder) {
  Rig rig;
  std::vector<std::string> trace;
  // Table order deliberately not alphabetical nor by rate.
  rig.add(spec("log", 10, 5, 1ms), 100us).trace_into(&trace);
  rig.add(spec("sense", 1, 0, 2ms), 100us).trace_into(&trace);
  rig.add(spec("plan", 3, 1, 3ms), 100us).trace_into(&trace);
  rig.add(spec("act", 1, 0, 1ms), 100us).trace_into(&trace);
  rig.build().run(30);

  std::vector<std::string> expected;
  for (std::uint64_t f = 0; f < 30; ++f) {
    const auto fs = std::to_string(f);
    if (f % 10 == 5) expected.push_back("log@" + fs);
    expected.push_back("sense@" + fs);
    if (f % 3 == 1) expected.push_back("plan@" + fs);
    expected.push_back("act@" + fs);
  }
  EXPECT_EQ(trace, expected);
  // Frame 25 has all four, in table order.
  const std::vector<std::string> frame25 = {"log@25", "sense@25", "plan@25", "act@25"};
  const auto it = std::search(trace.begin(), trace.end(), frame25.begin(), frame25.end());
  EXPECT_NE(it, trace.end());
}

}  // namespace
}  // namespace ringlet::executive::test
