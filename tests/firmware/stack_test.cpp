// The composed firmware on the simulated robot, in lockstep: the shipped mission completes with no
// overruns and no collisions, runs are bit-identical for a seed, 83 Hz works, the failsafe policy
// really stops the robot, and a table that does not match the firmware's tasks is refused.
#include <gtest/gtest.h>

#include <sstream>

#include "firmware_test_support.hpp"
#include "ringlet/firmware/mission_report.hpp"
#include "ringlet/firmware/mission_runner.hpp"
#include "ringlet/firmware/stack.hpp"

namespace ringlet::firmware {
namespace {

using test::parse_as_shipped;
using test::shipped_config_text;
using test::with_line;

struct Run {
  MissionSummary summary;
  std::uint64_t overruns = 0;
  std::uint64_t frame_overruns = 0;
  bool safe_state = false;
};

Run run(const std::string& text) {
  const auto cfg = parse_as_shipped(text);
  FirmwareStack stack(cfg);
  std::atomic<bool> interrupt{false};
  std::ostringstream log;
  const auto outcome = run_mission(stack, cfg.timeout_s, interrupt, log);
  Run r;
  r.summary = summarize(stack, outcome, stack.executive().failsafe_triggered() || outcome.watchdog_fired);
  for (const auto& st : stack.executive().task_stats()) r.overruns += st.overruns;
  r.frame_overruns = stack.executive().frame_stats().frame_overruns;
  r.safe_state = stack.robot().actuators().in_safe_state();
  return r;
}

// What the robot does must not depend on the speed of the build under test (qemu, sanitizers):
// these runs warn on overruns instead of acting on them, except where the policy is the point.
std::string shipped() { return test::warn_only(shipped_config_text()); }

TEST(FirmwareStack, ShippedMissionCompletesInLockstep) {
  const auto r = run(shipped());
  EXPECT_TRUE(r.summary.complete);
  EXPECT_EQ(r.summary.goals_reached, r.summary.goal_count);
  EXPECT_GT(r.summary.goal_count, 3U);
  EXPECT_EQ(r.summary.collisions, 0U);
  if (test::kNativeSpeed) {
    EXPECT_EQ(r.overruns, 0U);
    EXPECT_EQ(r.frame_overruns, 0U);
  }
  EXPECT_FALSE(r.summary.safe_state);
  EXPECT_TRUE(r.safe_state) << "a clean shutdown ends in the safe state";
  EXPECT_EQ(exit_code(r.summary), 0);
}

TEST(FirmwareStack, SameSeedSameTrajectoryOtherSeedOtherTrajectory) {
  const auto a = run(shipped());
  const auto b = run(shipped());
  const auto c = run(with_line(shipped(), "seed", "seed = 7"));
  EXPECT_EQ(a.summary.trajectory_hash, b.summary.trajectory_hash);
  EXPECT_EQ(a.summary.mission_seconds, b.summary.mission_seconds);
  EXPECT_NE(a.summary.trajectory_hash, c.summary.trajectory_hash) << "GPS noise must depend on the seed";
}

TEST(FirmwareStack, EightyThreeHertzCompletesTheMission) {
  const auto r = run(with_line(shipped(), "period_us", "period_us = 12000"));
  EXPECT_TRUE(r.summary.complete);
  EXPECT_EQ(r.summary.collisions, 0U);
}

TEST(FirmwareStack, FailsafePolicyCommandsTheSafeStateAndExitCodeSaysSo) {
  // 1 us of thread CPU time is less than one laser scan costs: the first activation overruns.
  const auto r = run(with_line(shipped_config_text(), "  { name = \"sense\"",
                               "  { name = \"sense\", budget_us = 1, policy = \"failsafe\" },"));
  EXPECT_TRUE(r.summary.failsafe);
  EXPECT_TRUE(r.summary.safe_state);
  EXPECT_FALSE(r.summary.complete);
  EXPECT_EQ(exit_code(r.summary), 4);
}

TEST(FirmwareStack, TimeoutIsAnIncompleteMission) {
  const auto r = run(with_line(shipped(), "timeout_s", "timeout_s = 5"));
  EXPECT_FALSE(r.summary.complete);
  EXPECT_NEAR(r.summary.mission_seconds, 5.0, 0.011);
  EXPECT_EQ(exit_code(r.summary), 3);
}

TEST(FirmwareStack, TableMustNameExactlyTheFirmwaresTasks) {
  const auto text = with_line(shipped_config_text(), "  { name = \"telemetry\"",
                              "  { name = \"vision\", every = 3, phase = 1, budget_us = 100 },");
  const auto cfg = parse_as_shipped(text);
  try {
    FirmwareStack stack(cfg);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("task 'vision' is not a task this firmware provides"), std::string::npos) << m;
    EXPECT_NE(m.find("task 'telemetry' is missing from the table"), std::string::npos) << m;
  }
}

TEST(FirmwareStack, CanBackendIsRefusedClearly) {
  const auto cfg = parse_as_shipped(with_line(shipped_config_text(), "backend", "backend = \"can\""));
  EXPECT_THROW({ FirmwareStack stack(cfg); }, ConfigError);
}

}  // namespace
}  // namespace ringlet::firmware
