// The cyclic executive on virtual time, stopping and resuming: request_stop from a task or from
// elsewhere, frame limits and resuming on the same grid, running without an event log.
#include <gtest/gtest.h>

#include "executive_test_support.hpp"
#include "ringlet/executive/executive.hpp"

namespace ringlet::executive::test {
namespace {

TEST(ExecutiveRun, RequestStopFromATaskEndsTheRunAfterThatFrame) {
  Rig rig;
  auto& boss = rig.add(spec("boss", 1, 0, 2ms), 1ms);
  boss.on_run([](const TaskContext& ctx) {
    if (ctx.frame == 7) ctx.request_stop();
  });
  auto& after = rig.add(spec("after", 1, 0, 2ms), 1ms);
  auto& exec = rig.build();

  EXPECT_EQ(exec.run(100), StopReason::kRequested);
  EXPECT_EQ(exec.frame_stats().frames, 8U);
  EXPECT_EQ(exec.next_frame(), 8U);
  ASSERT_FALSE(after.frames().empty());
  EXPECT_EQ(after.frames().back(), 7U);  // the rest of frame 7 still ran
  EXPECT_TRUE(exec.stop_flag().load());

  // The stop is latched (the watchdog also reads it as the shutdown flag) until cleared.
  EXPECT_EQ(exec.run(5), StopReason::kRequested);
  EXPECT_EQ(exec.frame_stats().frames, 8U);
  exec.stop_flag().store(false);
  EXPECT_EQ(exec.run(3), StopReason::kFrameLimit);
  EXPECT_EQ(boss.frames().back(), 10U);
  EXPECT_EQ(boss.activations().back().frame_start, due(10));
}

TEST(ExecutiveRun, RequestStopFromAnotherPlaceBeforeRunReturnsAtOnce) {
  Rig rig;
  auto& t = rig.add(spec("t", 1, 0, 2ms), 1ms);
  auto& exec = rig.build();
  exec.request_stop();
  EXPECT_EQ(exec.run(10), StopReason::kRequested);
  EXPECT_TRUE(t.frames().empty());
}

TEST(ExecutiveRun, FrameLimitThenResumeContinuesOnTheSameGrid) {
  Rig rig;
  auto& t = rig.add(spec("t", 1, 0, 2ms), 1ms);
  auto& slow = rig.add(spec("slow", 4, 2, 2ms), 1ms);
  auto& exec = rig.build();

  EXPECT_EQ(exec.run(5), StopReason::kFrameLimit);
  EXPECT_EQ(exec.next_frame(), 5U);
  EXPECT_EQ(exec.frame_stats().frames, 5U);
  EXPECT_EQ(exec.run(5), StopReason::kFrameLimit);
  EXPECT_EQ(exec.next_frame(), 10U);
  EXPECT_EQ(t.frames(), frames_where(10, 1, 0));
  EXPECT_EQ(slow.frames(), frames_where(10, 4, 2));
  EXPECT_EQ(t.activations()[5].frame_start, due(5));
  EXPECT_EQ(exec.heartbeat().load(), 10U);
}

TEST(ExecutiveRun, FrameLimitCountsSlippedFrames) {
  Rig rig;
  auto& t = rig.add(spec("t", 1, 0, 5ms), 1ms);
  t.cost_in_frame(5, 25ms);
  auto& exec = rig.build();
  EXPECT_EQ(exec.run(8), StopReason::kFrameLimit);  // frames 0..5 run, 6 and 7 slip
  EXPECT_EQ(exec.frame_stats().frames, 6U);
  EXPECT_EQ(exec.next_frame(), 8U);
  exec.run(1);
  EXPECT_EQ(t.frames().back(), 8U);
}

TEST(ExecutiveRun, EventsGoNowhereWithoutALog) {
  hal::VirtualClock clock;
  FakeActuators actuators;
  ScriptedTask t(clock, "t", 5ms);
  Executive exec(ExecutiveConfig{}, {TaskBinding{spec("t", 1, 0, 2ms, OverrunPolicy::kFailsafe), &t}}, clock, clock,
                 actuators, nullptr);
  exec.run(3);
  EXPECT_EQ(exec.task_stats()[0].overruns, 3U);
  EXPECT_TRUE(actuators.in_safe_state());
  EXPECT_EQ(exec.failsafe_task(), 0);
}

}  // namespace
}  // namespace ringlet::executive::test
