// The full simulated stack (camera and vision included) on the REAL clock for 2 s at 100 Hz: the
// executive sleeps to absolute deadlines with clock_nanosleep and measures every task. Asserted: each task's p99 thread CPU
// time is inside its budget (CPU time does not depend on what else this shared machine is doing).
// Wall-clock figures are printed for the record, never asserted.
#include <gtest/gtest.h>

#include <cstdio>

#include "firmware_test_support.hpp"
#include "ringlet/firmware/stack.hpp"

namespace ringlet::firmware {
namespace {

TEST(RealClock, TwoSecondsAt100HzKeepEveryTaskP99CpuInsideItsBudget) {
  // The main job's stack: camera (render thread) and vision included.
  auto text = test::shipped_config_text(test::kSplConfig);
  text = test::with_line(text, "clock", "clock = \"realtime\"");
  auto cfg = test::parse_as_shipped(text);
  ASSERT_EQ(cfg.clock, ClockMode::kRealtime);
  ASSERT_EQ(cfg.executive.period, hal::Nanos{10'000'000});
  FirmwareStack stack(cfg);
  auto& exec = stack.executive();
  constexpr std::uint64_t kFrames = 200;  // 2 s at 100 Hz
  exec.run(kFrames);

  const auto& frames = exec.frame_stats();
  // Every frame number up to the limit was run or slipped (a late last frame may slip a few more).
  EXPECT_GE(frames.frames + frames.slips, kFrames);
  EXPECT_LE(frames.frames, kFrames);
  const double slowdown = test::kCpuSlowdown;
  std::printf("real clock, %llu frames (slowdown factor for budgets: %.0f)\n",
              static_cast<unsigned long long>(frames.frames), slowdown);
  for (std::size_t i = 0; i < exec.tasks().size(); ++i) {
    const auto& spec = exec.tasks()[i].spec;
    const auto& st = exec.task_stats()[i];
    const double budget_us = hal::to_seconds(spec.budget) * 1e6 * slowdown;
    const double cpu_p99_us = hal::to_seconds(st.cpu.percentile(0.99)) * 1e6;
    std::printf("  %-10s runs %5llu  cpu p99 %8.1f us (budget %8.1f us)  wall p99 %8.1f us  wall max %8.1f us\n",
                spec.name.c_str(), static_cast<unsigned long long>(st.runs), cpu_p99_us, budget_us,
                hal::to_seconds(st.wall.percentile(0.99)) * 1e6, hal::to_seconds(st.wall.max()) * 1e6);
    EXPECT_GT(st.runs, 0U) << spec.name;
    EXPECT_LE(cpu_p99_us, budget_us) << spec.name << ": p99 thread CPU time over budget";
  }
  std::printf("  wake-up latency p99 %.1f us, max %.1f us; frame overruns %llu, slips %llu (not asserted)\n",
              hal::to_seconds(frames.wake_latency.percentile(0.99)) * 1e6,
              hal::to_seconds(frames.wake_latency.max()) * 1e6,
              static_cast<unsigned long long>(frames.frame_overruns), static_cast<unsigned long long>(frames.slips));
}

}  // namespace
}  // namespace ringlet::firmware
