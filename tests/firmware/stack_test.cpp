// The composed firmware on the simulated robot, in lockstep: the shipped mission completes with no
// overruns and no collisions, runs are bit-identical for a seed, 83 Hz works, the failsafe policy
// really stops the robot, and a table that does not match the firmware's tasks is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "firmware_test_support.hpp"
#include "ringlet/firmware/backend_factory.hpp"
#include "ringlet/firmware/mission_report.hpp"
#include "ringlet/firmware/mission_runner.hpp"
#include "ringlet/firmware/stack.hpp"
#include "ringlet/firmware/tasks/vision_task.hpp"
#include "ringlet/firmware/telemetry.hpp"

namespace ringlet::firmware {
namespace {

using test::parse_as_shipped;
using test::shipped_config_text;
using test::with_line;

struct Run {
  MissionSummary summary;
  executive::TaskStats vision_timing{};  // the vision task's row, when there is one
  std::vector<std::string> mission_states;  // Mission's FsmStatus states, as the whiteboard saw them
  std::string safety_state;
  std::uint64_t overruns = 0;
  std::uint64_t frame_overruns = 0;
  bool safe_state = false;
};

Run run(const std::string& text) {
  const auto cfg = parse_as_shipped(text);
  FirmwareStack stack(cfg);
  Run r;
  r.mission_states.reserve(1000);
  // Any whiteboard subscriber sees every FsmStatus (delivered at the whiteboard task's dispatch).
  stack.whiteboard().subscribe<wb::FsmStatus>([&r](const wb::FsmStatus& status) {
    if (status.machine.view() == "Mission") r.mission_states.emplace_back(status.state.view());
  });
  std::atomic<bool> interrupt{false};
  std::ostringstream log;
  const auto outcome = run_mission(stack, cfg.mission.timeout_s, interrupt, log);
  r.summary = summarize(stack, outcome, stack.executive().failsafe_triggered() || outcome.watchdog_fired);
  for (const auto& st : stack.executive().task_stats()) r.overruns += st.overruns;
  r.frame_overruns = stack.executive().frame_stats().frame_overruns;
  r.safe_state = stack.robot().actuators().in_safe_state();
  r.safety_state = std::string(stack.schedule().machine(stack.schedule().size() - 1).current_state_name());  // Safety runs last
  for (std::size_t i = 0; i < stack.executive().tasks().size(); ++i) {
    if (stack.executive().tasks()[i].spec.name == "vision") r.vision_timing = stack.executive().task_stats()[i];
  }
  return r;
}


// The shipped configurations as they are, policies included: in lockstep the policies act on the
// tasks' modelled costs, so what the robot does cannot depend on the speed of the build under
// test (qemu, sanitizers) or on the host's load.
std::string shipped() { return shipped_config_text(); }

TEST(FirmwareStack, ShippedMissionCompletesInLockstep) {
  const auto r = run(shipped());
  EXPECT_TRUE(r.summary.complete);
  EXPECT_EQ(r.summary.goals_reached, r.summary.goal_count);
  EXPECT_GT(r.summary.goal_count, 3U);
  EXPECT_EQ(r.summary.collisions, 0U);
  EXPECT_EQ(r.overruns, 0U) << "judged on the modelled costs, which the shipped budgets cover";
  EXPECT_EQ(r.frame_overruns, 0U) << "lockstep frames never overrun the virtual clock";
  EXPECT_FALSE(r.summary.safe_state);
  EXPECT_TRUE(r.safe_state) << "a clean shutdown ends in the safe state";
  EXPECT_EQ(exit_code(r.summary), 0);
}

TEST(FirmwareStack, TheThreeMachinesRunAndTheirStatusIsOnTheWhiteboard) {
  const auto r = run(shipped());
  ASSERT_EQ(r.summary.machines.size(), 3U);
  EXPECT_EQ(r.summary.machines[0].name, "BallTracker");
  EXPECT_EQ(r.summary.machines[1].name, "Mission");
  EXPECT_EQ(r.summary.machines[1].state, "Done");
  EXPECT_EQ(r.summary.machines[2].name, "Safety");
  EXPECT_EQ(r.summary.machines[2].state, "Clear");
  EXPECT_EQ(r.summary.machines[2].ringlets, 2 * r.summary.machines[0].ringlets) << "Safety runs twice a turn";
  // Every goal reached is a Reached state change that a whiteboard subscriber received.
  EXPECT_EQ(std::count(r.mission_states.begin(), r.mission_states.end(), "Reached"),
            static_cast<std::ptrdiff_t>(r.summary.goal_count));
  ASSERT_FALSE(r.mission_states.empty());
  EXPECT_EQ(r.mission_states.front(), "Drive") << "first change after subscribing: WaitForPose -> Drive";
  EXPECT_EQ(r.mission_states.back(), "Done");
  EXPECT_GT(r.summary.fsm_status_seen, 2 * r.summary.goal_count);
}

TEST(FirmwareStack, TheHeadTracksTheBall) {
  const auto r = run(shipped());
  ASSERT_TRUE(r.summary.truth.has_value()) << "the simulator has ground truth: the head is scored";
  ASSERT_GT(r.summary.truth->head.frames, 1000U);
  EXPECT_GT(r.summary.truth->head.on_target_share(), 0.95) << "head yaw within 5 degrees of the true ball";
  EXPECT_LT(r.summary.truth->head.mean_error(), 0.03);
}

TEST(FirmwareStack, SafetyMachineStopsTheRobotBeforeAWall) {
  // The shipped configuration on a corridor whose only goal lies behind a wall.
  const auto world = test::kShippedConfig.parent_path().parent_path().parent_path() / "tests/firmware/data/blocked.world";
  auto text = with_line(shipped(), "world", "world = \"" + world.string() + "\"");
  text = with_line(text, "timeout_s", "timeout_s = 20");
  text = with_line(text, "goals", "goals = [[2, 10]]");
  const auto r = run(text);
  EXPECT_FALSE(r.summary.complete);
  EXPECT_EQ(r.summary.collisions, 0U) << "the robot must stop before the wall";
  EXPECT_EQ(r.safety_state, "Stopped");
  EXPECT_GT(r.summary.distance_m, 3.0) << "it drove up the corridor first";
}

// The main job's scenario, shortened: the rendered camera feeds vision every third frame.
std::string spl(double seconds) {
  return with_line(shipped_config_text(test::kSplConfig), "timeout_s",
                   "timeout_s = " + std::to_string(seconds));
}

TEST(FirmwareVision, LinesAndBallAreDetectedAndTheHeadFollowsTheDetectedBall) {
  const auto r = run(spl(5.0));  // 5 s: among the longest tests under ASan and qemu
  ASSERT_TRUE(r.summary.vision.has_value());
  const VisionStats& v = *r.summary.vision;
  EXPECT_GE(v.frames, 160U) << "one frame every 3rd period for 5 s";
  EXPECT_EQ(v.bad_frames, 0U);
  EXPECT_EQ(v.missed_frames, 0U) << "in lockstep every rendered frame is processed";
  EXPECT_GT(static_cast<double>(v.with_lines), 0.95 * static_cast<double>(v.frames));
  EXPECT_GT(static_cast<double>(v.with_ball), 0.6 * static_cast<double>(v.frames));
  EXPECT_EQ(r.summary.collisions, 0U);
  // The ball belief comes from vision now, and the tracker keeps the head on the true ball.
  ASSERT_TRUE(r.summary.truth.has_value());
  EXPECT_GT(r.summary.truth->head.on_target_share(), 0.7);
  EXPECT_GE(r.vision_timing.runs, v.frames);
  EXPECT_LE(r.vision_timing.runs - v.frames, 2U) << "only the activations before the first frame have nothing to do";
  EXPECT_GT(v.robots, 0U) << "the field's robots are found by HOG";
  // The whole pipeline (lines, circle, marks, the black-and-white ball and the robots, both
  // verified by HOG/SVM) is an anytime pipeline: the classifiers take what the budget leaves, and
  // the line search is cut only rarely. Such a frame is overloaded, not an overrun, and the degrade
  // policy acts on it for a while (vision/README.md, "The modelled budget").
  EXPECT_EQ(r.vision_timing.overruns, 0U);
  EXPECT_LE(v.lines_cut * 20, v.frames) << "the line search cut in at most 5 % of the frames";
  EXPECT_EQ(r.vision_timing.overloads, v.lines_cut);
  EXPECT_LE(r.vision_timing.degraded_runs * 4, r.vision_timing.runs) << "at level 0 in at least 3 of 4 runs";
  EXPECT_LE(r.vision_timing.model.percentile(0.99), hal::Nanos{3'000'000}) << "inside the 3 ms vision budget";
  EXPECT_GT(r.vision_timing.model.min(), hal::Nanos{0});

  // Where the budget went (the report's breakdown by stage): one sample per frame and stage, adding
  // up to the model the executive judged (which adds VisionTask::kNoFrameCost per activation).
  std::int64_t staged_ns = 0;
  for (const auto& h : v.stage_model) {
    EXPECT_EQ(h.count(), v.frames);
    staged_ns += h.mean().count() * static_cast<std::int64_t>(h.count());
  }
  const auto runs = static_cast<std::int64_t>(r.vision_timing.runs);
  const std::int64_t judged_ns = (r.vision_timing.model.mean() - VisionTask::kNoFrameCost).count() * runs;
  EXPECT_NEAR(static_cast<double>(staged_ns), static_cast<double>(judged_ns), 16.0 * static_cast<double>(runs));
  const nlohmann::json stages = summary_json(r.summary).at("vision").at("stage_model");
  ASSERT_EQ(stages.size(), vision::kStageCount) << stages.dump();
  for (const char* busy : {"classify", "scan", "ransac", "ball", "robots"}) {
    EXPECT_GT(stages.at(busy).at("p50_us").get<double>(), 0.0) << busy << " did work in most frames";
  }
}

TEST(FirmwareVision, SameSeedSameRunWithTheCamera) {
  const auto a = run(spl(2.0));
  const auto b = run(spl(2.0));
  EXPECT_EQ(a.summary.trajectory_hash, b.summary.trajectory_hash);
  ASSERT_TRUE(a.summary.vision && b.summary.vision);
  EXPECT_EQ(a.summary.vision->lines, b.summary.vision->lines);
  EXPECT_EQ(a.summary.vision->with_ball, b.summary.vision->with_ball);
  ASSERT_TRUE(a.summary.truth && b.summary.truth);
  EXPECT_EQ(a.summary.truth->head.sum_error, b.summary.truth->head.sum_error) << "the head followed the same detections";
}

TEST(FirmwareVision, MissingColourTableIsAConfigError) {
  const auto cfg = parse_as_shipped(with_line(spl(1.0), "lut =", "lut = \"no-such-table.lut\""));
  try {
    FirmwareStack stack(cfg);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("vision.lut: colour table"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no-such-table.lut"), std::string::npos) << e.what();
  }
}

// The HOG/SVM model keys: a missing file, a file that is no model, and a model for the other
// target are refused at start-up naming the key, where it was written, and the file.
std::string vision_start_error(const std::string& key, const std::string& file) {
  const auto cfg = parse_as_shipped(with_line(spl(1.0), key + " =", key + " = \"" + file + "\""));
  try {
    FirmwareStack stack(cfg);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(FirmwareVision, BadHogModelsAreConfigErrors) {
  const std::string missing = vision_start_error("ball_model", "no-such-model.hog");
  EXPECT_NE(missing.find(".toml:"), std::string::npos) << missing;  // file:line:col of the key
  EXPECT_NE(missing.find("vision.ball_model: "), std::string::npos) << missing;
  EXPECT_NE(missing.find("no-such-model.hog"), std::string::npos) << missing;
  const std::string corrupt = vision_start_error("robot_model", "../../vision/models/robot.hog.recipe.txt");
  EXPECT_NE(corrupt.find("vision.robot_model: hog model "), std::string::npos) << corrupt;
  EXPECT_NE(corrupt.find("robot.hog.recipe.txt"), std::string::npos) << corrupt;
  const std::string swapped = vision_start_error("ball_model", "../../vision/models/robot.hog");
  EXPECT_NE(swapped.find("vision.ball_model: hog model "), std::string::npos) << swapped;
  EXPECT_NE(swapped.find("is a robot model, not a ball model"), std::string::npos) << swapped;
}

// The shipped models load, and the vision task provides RobotDetections (the contract check
// accepts the stack); without the robot stage the task still starts.
TEST(FirmwareVision, TheShippedModelsLoad) {
  auto text = with_line(spl(1.0), "ball =", "ball = \"bw\"");
  text = with_line(text, "ball_model =", "ball_model = \"../../vision/models/ball.hog\"");
  text = with_line(text, "robot_model =", "robot_model = \"../../vision/models/robot.hog\"");
  EXPECT_NO_THROW(FirmwareStack stack(parse_as_shipped(text)));
  EXPECT_NO_THROW(FirmwareStack stack(parse_as_shipped(with_line(text, "robots =", "robots = false"))));
}

TEST(FirmwareVision, WithoutAVisionTaskNothingProvidesTheBall) {
  const auto cfg = parse_as_shipped(with_line(spl(1.0), "  { name = \"vision\"", ""));
  try {
    FirmwareStack stack(cfg);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("machine 'BallTracker' requires 'BallBelief', but no task"), std::string::npos)
        << e.what();
  }
}

// A robot without a head camera (the CAN board of courtyard_can.toml): no ball task, and with
// [mission] ball_tracking = false no BallTracker either; the mission runs on the other two.
TEST(FirmwareStack, WithoutBallTrackingNoBallTaskIsNeededAndTheMissionCompletes) {
  std::string text = with_line(shipped(), "  { name = \"ball_sensor\"", "");
  text = with_line(text, "goal_tolerance_m", "goal_tolerance_m = 0.3\nball_tracking = false");
  const auto r = run(text);
  ASSERT_EQ(r.summary.machines.size(), 2U);
  EXPECT_EQ(r.summary.machines[0].name, "Mission");
  EXPECT_EQ(r.summary.machines[1].name, "Safety");
  EXPECT_TRUE(r.summary.complete);
  EXPECT_EQ(r.summary.collisions, 0U);
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
  // 1 us is less than the sense task's modelled cost: the first activation overruns.
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

TEST(FirmwareStack, TwoTasksMayNotProvideTheSameType) {
  // The courtyard with vision added beside the simulator's own ball sensor: both post BallBelief.
  const auto text = with_line(shipped_config_text(), "  { name = \"telemetry\"",
                              "  { name = \"vision\", every = 3, phase = 1, budget_us = 3000 },\n"
                              "  { name = \"telemetry\", every = 1, phase = 0, budget_us = 100, policy = \"skip\" },");
  const auto cfg = parse_as_shipped(text);
  try {
    FirmwareStack stack(cfg);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("tasks 'ball_sensor' and 'vision' both provide 'BallBelief': run one of them"), std::string::npos)
        << m;
  }
}

TEST(FirmwareStack, AMachineWhoseInputNobodyProvidesStopsStartUp) {
  // Without the goals task, the Mission machine's MissionGoals has no provider.
  const auto cfg = parse_as_shipped(with_line(shipped_config_text(), "  { name = \"goals\"", ""));
  try {
    FirmwareStack stack(cfg);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("machine 'Mission' requires 'MissionGoals', but no task in the table or machine provides it"),
              std::string::npos)
        << m;
  }
}

// The CAN board runs on the real clock: the shipped (lockstep) configuration with backend "can"
// parses, and building its robot is refused naming executive.clock.
TEST(FirmwareStack, TheCanBoardIsRefusedInLockstep) {
  const FirmwareConfig cfg = parse_as_shipped(with_line(shipped_config_text(), "backend", "backend = \"can\""));
  try {
    (void)make_robot(cfg);
    FAIL() << "a CAN robot in lockstep";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("executive.clock: the CAN board runs on the real clock"), std::string::npos) << e.what();
  }
}

// Per-goal times for the experiments: each goal is stamped with the frame it was first reported
// reached in; reports that repeat a count stamp nothing; more goals than it holds are not stamped.
TEST(Telemetry, StampsEachGoalWithTheFrameItWasFirstReportedReached) {
  Telemetry t(16, 4);
  t.record_progress(0, 3, 5);
  EXPECT_TRUE(t.goal_frames().empty());
  t.record_progress(1, 3, 7);
  t.record_progress(1, 3, 8);
  t.record_progress(3, 3, 12);  // two goals in one report: both stamped with its frame
  ASSERT_EQ(t.goal_frames().size(), 3U);
  EXPECT_EQ(t.goal_frames()[0], 7U);
  EXPECT_EQ(t.goal_frames()[1], 12U);
  EXPECT_EQ(t.goal_frames()[2], 12U);
  EXPECT_EQ(t.goals_reached(), 3U);
  Telemetry many(16, 4);
  many.record_progress(Telemetry::kMaxGoalFrames + 5, Telemetry::kMaxGoalFrames + 5, 1);
  EXPECT_EQ(many.goal_frames().size(), Telemetry::kMaxGoalFrames);
}

}  // namespace
}  // namespace ringlet::firmware
