// Record a simulated run's HAL inputs (--record) and replay them through the same firmware on the
// replay backend: the replayed whiteboard traffic equals the recorded one, message by message.
#include <gtest/gtest.h>

#include <atomic>
#include <fstream>
#include <unistd.h>
#include <filesystem>
#include <sstream>
#include <string>

#include "firmware_test_support.hpp"
#include "ringlet/firmware/mission_report.hpp"
#include "ringlet/firmware/mission_runner.hpp"
#include "ringlet/firmware/stack.hpp"
#include "ringlet/whiteboard/message_log.hpp"

namespace ringlet::firmware {
namespace {

using test::parse_as_shipped;
using test::shipped_config_text;
using test::with_line;

struct RunResult {
  MissionSummary summary;
  RunOutcome outcome;
  bool picture = false;
};

RunResult run(const FirmwareConfig& cfg) {
  FirmwareStack stack(cfg);
  std::atomic<bool> interrupt{false};
  std::ostringstream log;
  RunResult r;
  r.outcome = run_mission(stack, cfg.mission.timeout_s, interrupt, log);
  EXPECT_TRUE(stack.finish_logs().empty());
  r.summary = summarize(stack, r.outcome, false);
  std::ostringstream svg;
  r.picture = write_picture(svg, stack, r.summary);
  return r;
}

// The whiteboard log without ExecutiveTiming: that message carries the host's measured task
// times, which differ between any two runs by nature.
wb::MessageLog controller_messages(const std::filesystem::path& path) {
  const auto log = wb::read_message_log(path);
  EXPECT_TRUE(log.has_value()) << path;
  wb::MessageLog out = log.has_value() ? *log : wb::MessageLog{};
  wb::drop_host_measurements(out);
  return out;
}

std::string replay_of(const std::string& recorded_text, const std::filesystem::path& log) {
  return with_line(recorded_text, "backend", "backend = \"replay\"") + "\n[replay]\nlog = \"" + log.string() + "\"\n";
}

class Replay : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("ringlet_replay_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Records `text` with both logs, replays it, and checks the two whiteboard logs are the same.
  void record_and_replay(const std::string& text) {
    FirmwareConfig recorded = parse_as_shipped(text);
    recorded.record_log = dir_ / "run.hallog";
    recorded.whiteboard_log = dir_ / "recorded.wblog";
    const RunResult a = run(recorded);

    FirmwareConfig replayed = parse_as_shipped(replay_of(text, recorded.record_log));
    ASSERT_EQ(replayed.backend, "replay");
    replayed.whiteboard_log = dir_ / "replayed.wblog";
    const RunResult b = run(replayed);

    const wb::MessageLog want = controller_messages(recorded.whiteboard_log);
    const wb::MessageLog got = controller_messages(replayed.whiteboard_log);
    EXPECT_GT(want.messages.size(), 1000U);
    EXPECT_TRUE(want.complete && got.complete);
    const auto difference = wb::first_difference(want, got);
    EXPECT_FALSE(difference.has_value()) << *difference;

    EXPECT_EQ(a.summary.trajectory_hash, b.summary.trajectory_hash);
    EXPECT_EQ(a.summary.goals_reached, b.summary.goals_reached);
    EXPECT_EQ(a.summary.goal_count, b.summary.goal_count) << "the mission comes from the configuration";
    EXPECT_GT(b.summary.goal_count, 0U);
    EXPECT_TRUE(a.summary.truth.has_value()) << "the simulator has ground truth";
    EXPECT_FALSE(b.summary.truth.has_value()) << "a replay has none: its columns are left out";
    EXPECT_TRUE(a.picture);
    EXPECT_FALSE(b.picture) << "no truth, no world to draw";
    EXPECT_EQ(b.summary.backend, "replay");
  }

  std::filesystem::path dir_;
};

TEST_F(Replay, CourtyardReplaysToTheSameWhiteboardTraffic) {
  record_and_replay(with_line(shipped_config_text(), "timeout_s", "timeout_s = 6"));
}

TEST_F(Replay, SplFieldWithTheCameraReplaysToTheSameWhiteboardTraffic) {
  record_and_replay(with_line(shipped_config_text(test::kSplConfig), "timeout_s", "timeout_s = 1.5"));
}

TEST_F(Replay, TheRunEndsWhereTheLogEnds) {
  FirmwareConfig recorded = parse_as_shipped(with_line(shipped_config_text(), "timeout_s", "timeout_s = 1"));
  recorded.record_log = dir_ / "short.hallog";
  (void)run(recorded);
  const auto replayed = parse_as_shipped(replay_of(with_line(shipped_config_text(), "timeout_s", "timeout_s = 10"),
                                                   recorded.record_log));
  const RunResult r = run(replayed);
  EXPECT_EQ(r.outcome.reason, executive::StopReason::kRequested);
  EXPECT_NEAR(r.outcome.schedule_seconds, 1.01, 1e-9) << "100 recorded frames, then the frame that found the end";
}

TEST_F(Replay, ABadLogIsRefusedNamingTheKey) {
  const std::filesystem::path bogus = dir_ / "bogus.hallog";
  { std::ofstream(bogus) << "not a log"; }
  const auto cfg = parse_as_shipped(replay_of(shipped_config_text(), bogus));
  try {
    FirmwareStack stack(cfg);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("replay.log: " + bogus.string()), std::string::npos) << e.what();
  }
}

TEST_F(Replay, ARealTimeReplayIsRefused) {
  FirmwareConfig recorded = parse_as_shipped(with_line(shipped_config_text(), "timeout_s", "timeout_s = 0.1"));
  recorded.record_log = dir_ / "tiny.hallog";
  (void)run(recorded);
  auto cfg = parse_as_shipped(replay_of(shipped_config_text(), recorded.record_log));
  cfg.clock = ClockMode::kRealtime;
  try {
    FirmwareStack stack(cfg);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("executive.clock: a replay runs in lockstep"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ringlet::firmware
