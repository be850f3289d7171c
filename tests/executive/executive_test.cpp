// The cyclic executive on virtual time: activations, order, budgets, frame overruns and slips,
// overrun policies, the context handed to tasks, stopping and resuming.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "executive_test_support.hpp"
#include "ringlet/executive/executive.hpp"

namespace ringlet::executive::test {
namespace {

constexpr Nanos kPeriod = 10ms;

std::vector<std::uint64_t> frames_where(std::uint64_t end, int every, int phase) {
  std::vector<std::uint64_t> out;
  for (std::uint64_t f = 0; f < end; ++f) {
    if (f % static_cast<std::uint64_t>(every) == static_cast<std::uint64_t>(phase)) out.push_back(f);
  }
  return out;
}

Nanos due(std::uint64_t frame) { return kStart + static_cast<std::int64_t>(frame) * kPeriod; }

// ---------------------------------------------------------------------------------------------
// Budgets met

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

// ---------------------------------------------------------------------------------------------
// Overruns

TEST(ExecutiveOverrun, SingleTaskOverrunCountedOnce) {
  Rig rig;
  auto& a = rig.add(spec("a", 1, 0, 2ms), 1ms);
  a.cost_in_frame(7, 4ms);
  auto& b = rig.add(spec("b", 1, 0, 2ms), 1ms);
  auto& exec = rig.build();
  exec.run(20);

  const auto stats = exec.task_stats();
  EXPECT_EQ(stats[0].overruns, 1U);
  EXPECT_EQ(stats[0].runs, 20U);
  EXPECT_EQ(stats[0].wall.max(), 4ms);
  EXPECT_EQ(stats[0].wall.min(), 1ms);
  EXPECT_EQ(stats[1].overruns, 0U);
  EXPECT_EQ(exec.frame_stats().frame_overruns, 0U);  // 5 ms of a 10 ms frame
  EXPECT_EQ(exec.frame_stats().slips, 0U);
  EXPECT_EQ(exec.frame_stats().frames, 20U);
  EXPECT_EQ(exec.frame_stats().busy.max(), 5ms);
  EXPECT_EQ(b.activations()[7].now, due(7) + 4ms);
  EXPECT_EQ(b.activations()[8].now, due(8) + 1ms);  // back to a's usual 1 ms

  const auto events = rig.drain();
  ASSERT_EQ(events.size(), 1U);
  EXPECT_EQ(events[0].kind, EventKind::kOverrun);
  EXPECT_EQ(events[0].task, 0U);
  EXPECT_EQ(events[0].frame, 7U);
  EXPECT_EQ(events[0].measured, 4ms);
  EXPECT_EQ(events[0].limit, 2ms);
  EXPECT_EQ(events[0].suppressed, 0U);
}

TEST(ExecutiveOverrun, CostEqualToBudgetIsNotAnOverrun) {
  Rig rig;
  rig.add(spec("exact", 1, 0, 2ms), 2ms);
  rig.add(spec("one_more", 1, 0, 2ms), 2ms + Nanos{1});
  auto& exec = rig.build();
  exec.run(5);
  EXPECT_EQ(exec.task_stats()[0].overruns, 0U);
  EXPECT_EQ(exec.task_stats()[1].overruns, 5U);
}

TEST(ExecutiveOverrun, FrameOverrunSlipsKeepingPhaseWithoutBurst) {
  Rig rig;
  auto& hog = rig.add(spec("hog", 1, 0, 5ms), 1ms);
  hog.cost_in_frame(5, 25ms);
  auto& third = rig.add(spec("third", 3, 0, 1ms), 500us);      // frames 0,3,6,9: loses 6
  auto& odd = rig.add(spec("odd", 2, 1, 1ms), 500us);          // frames 1,3,5,7,9,11: loses 7
  auto& quarter = rig.add(spec("quarter", 4, 1, 1ms), 500us);  // frames 1,5,9: loses none
  auto& exec = rig.build();

  EXPECT_EQ(exec.run(12), StopReason::kFrameLimit);

  const std::vector<std::uint64_t> ran = {0, 1, 2, 3, 4, 5, 8, 9, 10, 11};
  EXPECT_EQ(hog.frames(), ran);  // 6 and 7 never ran: no burst
  EXPECT_EQ(third.frames(), (std::vector<std::uint64_t>{0, 3, 9}));
  EXPECT_EQ(odd.frames(), (std::vector<std::uint64_t>{1, 3, 5, 9, 11}));
  EXPECT_EQ(quarter.frames(), (std::vector<std::uint64_t>{1, 5, 9}));

  // The activation after the overrun is frame 8, due exactly on the original grid.
  const auto& after = hog.activations()[6];
  EXPECT_EQ(after.frame, 8U);
  EXPECT_EQ(after.frame_start, due(8));
  EXPECT_EQ(after.now, due(8));
  EXPECT_EQ(hog.activations()[7].frame_start, due(9));

  const auto& f = exec.frame_stats();
  EXPECT_EQ(f.frames, 10U);
  EXPECT_EQ(f.frame_overruns, 1U);
  EXPECT_EQ(f.slips, 2U);
  EXPECT_EQ(f.wake_latency.max(), Nanos{0});
  EXPECT_EQ(f.busy.max(), 26ms);  // hog 25 ms + odd + quarter
  EXPECT_EQ(exec.next_frame(), 12U);

  const auto stats = exec.task_stats();
  EXPECT_EQ(stats[0].skipped, 2U);
  EXPECT_EQ(stats[1].skipped, 1U);
  EXPECT_EQ(stats[2].skipped, 1U);
  EXPECT_EQ(stats[3].skipped, 0U);
  EXPECT_EQ(stats[0].overruns, 1U);

  const auto events = rig.drain();
  const auto frame_events = of_kind(events, EventKind::kFrameOverrun);
  ASSERT_EQ(frame_events.size(), 1U);
  EXPECT_EQ(frame_events[0].frame, 5U);
  EXPECT_EQ(frame_events[0].measured, 26ms);
  EXPECT_EQ(frame_events[0].limit, kPeriod);
  EXPECT_EQ(frame_events[0].suppressed, 2U);  // frames lost
  EXPECT_EQ(of_kind(events, EventKind::kOverrun).size(), 1U);
}

TEST(ExecutiveOverrun, FrameEndingExactlyWhenTheNextIsDueIsNotAnOverrun) {
  Rig rig;
  auto& t = rig.add(spec("t", 1, 0, 5ms), 1ms);
  t.cost_in_frame(2, kPeriod);
  auto& exec = rig.build();
  exec.run(5);
  EXPECT_EQ(t.frames(), (std::vector<std::uint64_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(exec.frame_stats().frame_overruns, 0U);
  EXPECT_EQ(exec.frame_stats().slips, 0U);
  EXPECT_EQ(exec.task_stats()[0].overruns, 1U);
}

TEST(ExecutiveOverrun, FrameEndingOnALaterGridPointResumesThere) {
  Rig rig;
  auto& t = rig.add(spec("t", 1, 0, 5ms), 1ms);
  t.cost_in_frame(2, 3 * kPeriod);  // ends exactly when frame 5 is due
  auto& exec = rig.build();
  exec.run(8);
  EXPECT_EQ(t.frames(), (std::vector<std::uint64_t>{0, 1, 2, 5, 6, 7}));
  EXPECT_EQ(exec.frame_stats().slips, 2U);
  EXPECT_EQ(t.activations()[3].now, due(5));
}

TEST(ExecutiveOverrun, FrameOverrunWarningsAreRateLimited) {
  Rig rig;
  auto& t = rig.add(spec("t", 1, 0, 5ms), 1ms);
  for (std::uint64_t f = 0; f < 100; f += 2) t.cost_in_frame(f, 15ms);  // every executed frame overruns
  ExecutiveConfig cfg;
  cfg.warn_every_frames = 20;
  auto& exec = rig.build(cfg);
  exec.run(60);
  EXPECT_EQ(exec.frame_stats().frame_overruns, 30U);
  EXPECT_EQ(exec.frame_stats().slips, 30U);
  const auto frame_events = of_kind(rig.drain(), EventKind::kFrameOverrun);
  ASSERT_EQ(frame_events.size(), 3U);
  EXPECT_EQ(frame_events[0].frame, 0U);
  EXPECT_EQ(frame_events[1].frame, 20U);
  EXPECT_EQ(frame_events[2].frame, 40U);
}

// ---------------------------------------------------------------------------------------------
// Policies

TEST(ExecutivePolicy, WarnCountsEveryOverrunAndRateLimitsTheEvents) {
  Rig rig;
  auto& t = rig.add(spec("slow", 1, 0, 2ms, OverrunPolicy::kWarn), 3ms);
  for (std::uint64_t f = 25; f < 40; ++f) t.cost_in_frame(f, 1ms);  // a quiet spell, then late again
  ExecutiveConfig cfg;
  cfg.warn_every_frames = 10;
  auto& exec = rig.build(cfg);
  exec.run(25);  // frames 0..24 all overrun

  const auto& s = exec.task_stats()[0];
  EXPECT_EQ(s.overruns, 25U);
  EXPECT_EQ(s.runs, 25U);
  EXPECT_EQ(s.skipped, 0U);
  auto events = rig.drain();
  ASSERT_EQ(events.size(), 3U);
  EXPECT_EQ(events[0].frame, 0U);
  EXPECT_EQ(events[0].suppressed, 0U);
  EXPECT_EQ(events[1].frame, 10U);
  EXPECT_EQ(events[1].suppressed, 9U);  // frames 1..9
  EXPECT_EQ(events[2].frame, 20U);
  EXPECT_EQ(events[2].suppressed, 9U);
  EXPECT_EQ(s.suppressed_warnings, 4U);  // frames 21..24, reported with the next warning

  exec.run(25);  // frames 25..49: the only overruns are 40..49
  events = rig.drain();
  ASSERT_GE(events.size(), 1U);
  EXPECT_EQ(events[0].frame, 40U);
  EXPECT_EQ(events[0].suppressed, 4U);
  EXPECT_EQ(events.size(), 1U);  // 41..49 are within 10 frames of 40
  EXPECT_EQ(exec.task_stats()[0].overruns, 35U);
}

TEST(ExecutivePolicy, SkipSkipsTheNextActivationOnly) {
  Rig rig;
  auto& t = rig.add(spec("skippy", 1, 0, 2ms, OverrunPolicy::kSkip), 1ms);
  t.cost_in_frame(3, 3ms);
  auto& slow = rig.add(spec("every3", 3, 0, 2ms, OverrunPolicy::kSkip), 1ms);
  slow.cost_in_frame(3, 5ms);  // next activation is frame 6: skipped; 9 runs
  auto& exec = rig.build();
  exec.run(12);

  EXPECT_EQ(t.frames(), (std::vector<std::uint64_t>{0, 1, 2, 3, 5, 6, 7, 8, 9, 10, 11}));
  EXPECT_EQ(slow.frames(), (std::vector<std::uint64_t>{0, 3, 9}));
  const auto stats = exec.task_stats();
  EXPECT_EQ(stats[0].skipped, 1U);
  EXPECT_EQ(stats[0].overruns, 1U);
  EXPECT_EQ(stats[0].runs, 11U);
  EXPECT_EQ(stats[1].skipped, 1U);
  EXPECT_EQ(stats[1].runs, 3U);
}

TEST(ExecutivePolicy, SkipUnderPersistentOverrunRunsEveryOtherActivation) {
  Rig rig;
  auto& t = rig.add(spec("always_late", 1, 0, 2ms, OverrunPolicy::kSkip), 3ms);
  auto& exec = rig.build();
  exec.run(10);
  EXPECT_EQ(t.frames(), (std::vector<std::uint64_t>{0, 2, 4, 6, 8}));
  EXPECT_EQ(exec.task_stats()[0].overruns, 5U);
  EXPECT_EQ(exec.task_stats()[0].skipped, 5U);
}

TEST(ExecutivePolicy, DegradeRaisesLevelToMaxAndRecoversAfterCleanRuns) {
  Rig rig;
  auto& t = rig.add(spec("vision", 1, 0, 2ms, OverrunPolicy::kDegrade), 1ms);
  t.cost_by_activation([](std::size_t n) -> Nanos { return n < 5 ? 3ms : 1ms; });  // 5 overruns, then clean
  ExecutiveConfig cfg;
  cfg.degrade_max_level = 3;
  cfg.degrade_recover_after = 4;
  auto& exec = rig.build(cfg);
  exec.run(20);

  std::vector<int> levels;
  for (const auto& ctx : t.activations()) levels.push_back(ctx.degrade_level);
  const std::vector<int> expected = {0, 1, 2, 3, 3,   // rising, capped at 3
                                     3, 3, 3, 3,      // 4 clean runs at 3
                                     2, 2, 2, 2,      // 4 clean runs at 2
                                     1, 1, 1, 1,      // 4 clean runs at 1
                                     0, 0, 0};
  EXPECT_EQ(levels, expected);
  const auto& s = exec.task_stats()[0];
  EXPECT_EQ(s.degrade_level, 0);
  EXPECT_EQ(s.overruns, 5U);
  EXPECT_EQ(s.degraded_runs, 16U);
  EXPECT_EQ(s.runs, 20U);
  const auto events = of_kind(rig.drain(), EventKind::kOverrun);
  ASSERT_EQ(events.size(), 1U);  // rate limited (warn_every_frames = 100)
  EXPECT_EQ(events[0].level, 1);
}

TEST(ExecutivePolicy, DegradeOverrunDuringRecoveryRestartsTheCleanStreak) {
  Rig rig;
  auto& t = rig.add(spec("vision", 1, 0, 2ms, OverrunPolicy::kDegrade), 1ms);
  // Overrun, 2 clean, overrun, then clean.
  t.cost_by_activation([](std::size_t n) -> Nanos { return n == 0 || n == 3 ? 3ms : 1ms; });
  ExecutiveConfig cfg;
  cfg.degrade_max_level = 5;
  cfg.degrade_recover_after = 3;
  auto& exec = rig.build(cfg);
  exec.run(12);
  std::vector<int> levels;
  for (const auto& ctx : t.activations()) levels.push_back(ctx.degrade_level);
  EXPECT_EQ(levels, (std::vector<int>{0, 1, 1, 1, 2, 2, 2, 1, 1, 1, 0, 0}));
}

TEST(ExecutivePolicy, DegradeTellsTheTaskWhichCanRecoverByDoingLess) {
  // A task that does less when degraded: cost 3 ms at level 0 (over its 2 ms budget), 1 ms at >0.
  Rig rig;
  auto& t = rig.add(spec("adaptive", 1, 0, 2ms, OverrunPolicy::kDegrade), 0ms);
  const auto& acts = t.activations();
  t.cost_by_activation([&acts](std::size_t n) -> Nanos { return acts[n].degrade_level == 0 ? 3ms : 1ms; });
  ExecutiveConfig cfg;
  cfg.degrade_recover_after = 5;
  auto& exec = rig.build(cfg);
  exec.run(30);
  // Overrun at 0, degraded for 5 clean runs, back to 0, overrun again: period of 6 activations.
  EXPECT_EQ(exec.task_stats()[0].overruns, 5U);
  EXPECT_EQ(exec.task_stats()[0].degraded_runs, 25U);
}

TEST(ExecutivePolicy, FailsafeCommandsTheSafeStateAndNamesTheTask) {
  Rig rig;
  rig.add(spec("harmless", 1, 0, 2ms, OverrunPolicy::kWarn), 3ms);  // overruns every frame: no failsafe
  auto& critical = rig.add(spec("motion", 1, 0, 2ms, OverrunPolicy::kFailsafe), 1ms);
  critical.cost_in_frame(4, 3ms);
  critical.cost_in_frame(8, 3ms);
  auto& exec = rig.build();

  exec.run(4);
  EXPECT_FALSE(rig.actuators.in_safe_state());
  EXPECT_FALSE(exec.failsafe_triggered());
  EXPECT_EQ(exec.failsafe_task(), -1);

  exec.run(6);  // frames 4..9
  EXPECT_TRUE(rig.actuators.in_safe_state());
  EXPECT_EQ(rig.actuators.safe_calls(), 2);  // every failsafe overrun commands it again
  EXPECT_TRUE(exec.failsafe_triggered());
  EXPECT_EQ(exec.failsafe_task(), 1);
  EXPECT_EQ(exec.task_stats()[1].overruns, 2U);

  const auto failsafe = of_kind(rig.drain(), EventKind::kFailsafe);
  ASSERT_EQ(failsafe.size(), 1U);
  EXPECT_EQ(failsafe[0].task, 1U);
  EXPECT_EQ(failsafe[0].frame, 4U);
  EXPECT_EQ(failsafe[0].measured, 3ms);
  EXPECT_EQ(failsafe[0].limit, 2ms);
}

// ---------------------------------------------------------------------------------------------
// What a task is told

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

// Lockstep: the policy acts on the modelled cost, whatever the host measured; the measured
// overruns are counted beside it and change nothing.
TEST(ExecutiveModel, PoliciesActOnTheModelledCostNotOnTheMeasuredTime) {
  Rig rig;
  // Measured: every activation 6 ms against a 4 ms budget (a slow or loaded host).
  // Modelled: over budget in activations 2 and 5 only.
  rig.add(spec("vision", 1, 0, 4ms, OverrunPolicy::kSkip), 6ms).model_by_activation([](std::size_t n) {
    return n == 2 || n == 5 ? 5ms : 3ms;
  });
  ExecutiveConfig cfg;
  cfg.judge_on_model = true;
  auto& exec = rig.build(cfg);
  exec.run(10);
  const auto& s = exec.task_stats()[0];
  EXPECT_EQ(s.overruns, 2U) << "judged on the model";
  EXPECT_EQ(s.skipped, 2U) << "the skip policy acted on the modelled overruns only";
  EXPECT_EQ(s.runs, 8U);
  EXPECT_EQ(s.measured_overruns, 8U) << "every run was over budget on the measured clock";
  EXPECT_EQ(s.model.max(), 5ms);
  EXPECT_EQ(s.wall.max(), 6ms);
  // The overrun event carries the modelled cost.
  const auto overruns = of_kind(rig.drain(), EventKind::kOverrun);
  ASSERT_FALSE(overruns.empty());
  EXPECT_EQ(overruns.front().measured, 5ms);
}

TEST(ExecutiveModel, SameModelSameDecisionsWhateverTheMeasuredTimes) {
  // Two hosts: one fast, one slow and jittery. The degrade decisions are identical.
  std::vector<std::uint64_t> degraded;
  std::vector<std::vector<int>> levels(2);
  for (int host = 0; host < 2; ++host) {
    Rig rig;
    auto& t = rig.add(spec("vision", 1, 0, 4ms, OverrunPolicy::kDegrade), 1ms);
    t.cost_by_activation([host](std::size_t n) { return host == 0 ? 1ms : Nanos{(n * 7919 % 13) * 1'000'000}; });
    t.model_by_activation([](std::size_t n) { return n % 7 == 3 ? 6ms : 2ms; });
    t.on_run([&levels, host](const TaskContext& ctx) { levels[static_cast<std::size_t>(host)].push_back(ctx.degrade_level); });
    ExecutiveConfig cfg;
    cfg.judge_on_model = true;
    cfg.degrade_recover_after = 3;
    cfg.period = 20ms;
    auto& exec = rig.build(cfg);
    exec.run(60);
    degraded.push_back(exec.task_stats()[0].degraded_runs);
  }
  EXPECT_EQ(levels[0], levels[1]);
  EXPECT_EQ(degraded[0], degraded[1]);
  EXPECT_GT(degraded[0], 0U);
}

TEST(ExecutiveModel, WithoutTheModelTheMeasuredTimeIsJudgedAsBefore) {
  Rig rig;
  rig.add(spec("vision", 1, 0, 4ms, OverrunPolicy::kSkip), 6ms).model_by_activation([](std::size_t) { return 1ms; });
  auto& exec = rig.build();
  exec.run(10);
  EXPECT_EQ(exec.task_stats()[0].overruns, 5U);
  EXPECT_EQ(exec.task_stats()[0].measured_overruns, 5U);
}

// ---------------------------------------------------------------------------------------------
// Stopping and resuming

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
