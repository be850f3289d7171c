// The cyclic executive on virtual time, overruns: a task over its budget, a frame over its period
// (slips that keep the phase without a burst), and the rate limit on their warnings.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "executive_test_support.hpp"
#include "ringlet/executive/executive.hpp"

namespace ringlet::executive::test {
namespace {

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

}  // namespace
}  // namespace ringlet::executive::test
