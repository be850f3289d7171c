// The cyclic executive on virtual time, what a task is told: its deadline (the budget clipped to
// the frame end), the time left, and budgets judged on CPU time when asked.
#include <gtest/gtest.h>

#include <vector>

#include "executive_test_support.hpp"
#include "ringlet/executive/executive.hpp"

namespace ringlet::executive::test {
namespace {

TEST(ExecutiveContext, DeadlineIsBudgetClippedToTheFrameEnd) {
  Rig rig;
  auto& first = rig.add(spec("first", 1, 0, 4ms), 8ms);  // overruns: uses 8 ms of the frame
  auto& second = rig.add(spec("second", 1, 0, 5ms), 1ms);
  auto& third = rig.add(spec("third", 2, 1, Nanos{500us}), 100us);
  auto& exec = rig.build();
  exec.run(4);

  const auto& a = first.activations()[3];
  EXPECT_EQ(a.frame, 3U);
  EXPECT_EQ(a.frame_start, due(3));
  EXPECT_EQ(a.now, due(3));
  EXPECT_EQ(a.deadline, due(3) + 4ms);
  EXPECT_EQ(a.budget, 4ms);
  EXPECT_EQ(a.period, kPeriod);
  EXPECT_EQ(a.degrade_level, 0);
  EXPECT_NE(a.stopwatch, nullptr);
  EXPECT_NE(a.stop_flag, nullptr);

  const auto& b = second.activations()[3];
  EXPECT_EQ(b.now, due(3) + 8ms);
  EXPECT_EQ(b.deadline, due(3) + kPeriod);  // clipped: now + budget would be 13 ms
  EXPECT_EQ(b.budget, 2ms);
  EXPECT_EQ(b.started_wall, b.now);         // the virtual clock is also the stopwatch

  const auto& c = third.activations()[1];  // frame 3 again; 9 ms used, 1 ms left, budget 0.5 ms
  EXPECT_EQ(c.frame, 3U);
  EXPECT_EQ(c.now, due(3) + 9ms);
  EXPECT_EQ(c.deadline, due(3) + 9ms + 500us);
  EXPECT_EQ(c.budget, 500us);
}

TEST(ExecutiveContext, TimeLeftTracksInjectedTime) {
  Rig rig;
  std::vector<Nanos> left;
  std::vector<bool> out;
  auto& t = rig.add(spec("worker", 1, 0, 4ms), 0ms);
  auto& clock = rig.clock;
  t.on_run([&](const TaskContext& ctx) {
    left.push_back(ctx.time_left());
    out.push_back(ctx.out_of_time());
    clock.advance(3ms);
    left.push_back(ctx.time_left());
    out.push_back(ctx.out_of_time());
    clock.advance(1ms);  // exactly at the budget
    left.push_back(ctx.time_left());
    out.push_back(ctx.out_of_time());
    clock.advance(Nanos{1});
    left.push_back(ctx.time_left());
    out.push_back(ctx.out_of_time());
  });
  auto& exec = rig.build();
  exec.run(1);
  EXPECT_EQ(left, (std::vector<Nanos>{4ms, 1ms, Nanos{0}, Nanos{-1}}));
  EXPECT_EQ(out, (std::vector<bool>{false, false, true, true}));
  EXPECT_EQ(exec.task_stats()[0].overruns, 1U);  // 4 ms + 1 ns
}

TEST(ExecutiveContext, BudgetsJudgedOnCpuTimeWhenAsked) {
  for (const bool on_cpu : {false, true}) {
    Rig rig;
    HalfRateCpuStopwatch stopwatch(rig.clock);
    rig.add(spec("preempted", 1, 0, 4ms), 6ms);  // 6 ms wall, 3 ms CPU
    ExecutiveConfig cfg;
    cfg.overrun_on_cpu_time = on_cpu;
    auto& exec = rig.build(cfg, &stopwatch);
    exec.run(5);
    const auto& s = exec.task_stats()[0];
    EXPECT_EQ(s.wall.max(), 6ms);
    EXPECT_EQ(s.cpu.max(), 3ms);
    EXPECT_EQ(s.overruns, on_cpu ? 0U : 5U) << "overrun_on_cpu_time=" << on_cpu;
  }
}

}  // namespace
}  // namespace ringlet::executive::test
