// The cyclic executive on virtual time, overrun policies: warn, skip, degrade (and recovery),
// failsafe.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "executive_test_support.hpp"
#include "ringlet/executive/executive.hpp"

namespace ringlet::executive::test {
namespace {

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

TEST(ExecutivePolicy, AnOverloadedTaskIsDegradedButNotCountedAsAnOverrun) {
  // Activations 0 and 1 keep their budget only by cutting needed work (Task::overloaded): the
  // degrade policy lowers the next activations' work as after an overrun, and recovers the same way.
  Rig rig;
  auto& t = rig.add(spec("anytime", 1, 0, 2ms, OverrunPolicy::kDegrade), 1ms);
  t.overloaded_by_activation([](std::size_t n) { return n < 2; });
  auto& warned = rig.add(spec("warned", 1, 0, 2ms, OverrunPolicy::kWarn), 1ms);
  warned.overloaded_by_activation([](std::size_t n) { return n < 2; });
  ExecutiveConfig cfg;
  cfg.degrade_recover_after = 3;
  auto& exec = rig.build(cfg);
  exec.run(10);
  std::vector<int> levels;
  for (const auto& ctx : t.activations()) levels.push_back(ctx.degrade_level);
  EXPECT_EQ(levels, (std::vector<int>{0, 1, 2, 2, 2, 1, 1, 1, 0, 0}));
  const auto stats = exec.task_stats();
  EXPECT_EQ(stats[0].overruns, 0U);
  EXPECT_EQ(stats[0].overloads, 2U);
  EXPECT_EQ(stats[0].degraded_runs, 7U);
  EXPECT_TRUE(of_kind(rig.drain(), EventKind::kOverrun).empty()) << "no overrun warning: the budget was kept";
  // Another policy only counts it: nothing to lower.
  EXPECT_EQ(stats[1].overloads, 2U);
  EXPECT_EQ(stats[1].overruns, 0U);
  EXPECT_EQ(stats[1].degraded_runs, 0U);
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

}  // namespace
}  // namespace ringlet::executive::test
