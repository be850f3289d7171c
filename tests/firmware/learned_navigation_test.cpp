// The learned cost model in the cycle (issue 14): the [planner] keys and their errors, experiences
// recorded in a lockstep mission and written to a file that loads back, online learning that
// leaves a lockstep run bit-identical and every planner slice inside its budget.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "firmware_test_support.hpp"
#include "ringlet/firmware/mission_report.hpp"
#include "ringlet/firmware/mission_runner.hpp"
#include "ringlet/firmware/stack.hpp"
#include "ringlet/firmware/tasks/planner_task.hpp"
#include "ringlet/planning/experience_file.hpp"
#include "temp_dir.hpp"

namespace ringlet::firmware {
namespace {

using test::parse_as_shipped;
using test::shipped_config_text;
using test::with_line;
using test::error_of;

const std::filesystem::path kTraining = test::kShippedConfig.parent_path() / "pb_training.toml";

/// pb_training.toml with `planner_lines` added to [planner] and the mission cut to `seconds`.
std::string training(const std::string& planner_lines, double seconds) {
  std::string text = with_line(shipped_config_text(kTraining), "pops_per_slice",
                               "pops_per_slice = 2000\n" + planner_lines);
  return seconds > 0.0 ? with_line(text, "timeout_s", "timeout_s = " + std::to_string(seconds)) : text;
}

struct LearnedRun {
  MissionSummary summary;
  executive::TaskStats planner{};
  hal::Nanos budget{0};
  std::vector<planning::Experience> experiences;
  std::uint64_t publishes = 0;
  std::vector<hal::Pose2> trajectory;
};

LearnedRun run(const std::string& text) {
  const auto cfg = parse_as_shipped(text);
  FirmwareStack stack(cfg);
  const auto outcome = test::run_to_end(stack, cfg);
  EXPECT_TRUE(outcome.experiences_error.empty()) << outcome.experiences_error;
  LearnedRun r;
  r.summary = summarize(stack, outcome, stack.executive().failsafe_triggered() || outcome.watchdog_fired);
  const auto& tasks = stack.executive().tasks();
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    if (tasks[i].spec.name != "planner") continue;
    r.planner = stack.executive().task_stats()[i];
    r.budget = tasks[i].spec.budget;
    r.publishes = static_cast<const PlannerTask*>(tasks[i].task)->publishes();
  }
  const auto e = stack.experiences().experiences();
  r.experiences.assign(e.begin(), e.end());
  const auto t = stack.telemetry().trajectory();
  r.trajectory.assign(t.begin(), t.end());
  return r;
}

TEST(LearnedNavigationConfig, KeysAreCheckedWithTheirPlace) {
  EXPECT_NE(error_of(training("cost_model = \"neural\"", 0)).find("planner.cost_model: must be one of \"binary\", \"knn\""),
            std::string::npos);
  EXPECT_NE(error_of(training("cost_model = \"knn\"\nk = 65", 0)).find("planner.k: must be between 1 and 64"),
            std::string::npos);
  const std::string binary_k = error_of(training("k = 5", 0));
  EXPECT_EQ(binary_k.rfind(test::kShippedConfig.string() + ":", 0), 0U) << binary_k;  // file:line:col first
  EXPECT_NE(binary_k.find("planner.k: applies to cost_model = \"knn\" only"), std::string::npos) << binary_k;
  EXPECT_NE(error_of(training("capacity = 0", 0)).find("planner.capacity: must be between 1"), std::string::npos);
  const auto cfg = parse_as_shipped(training(
      "cost_model = \"knn\"\nk = 7\ndistance_weighted = true\nlearn_online = true\npublish_every = 30\nrecord = \"x.exp\"", 0));
  EXPECT_EQ(cfg.planner.cost_model, CostModelKind::kKnn);
  EXPECT_EQ(cfg.planner.knn.k, 7);
  EXPECT_TRUE(cfg.planner.knn.distance_weighted);
  EXPECT_TRUE(cfg.planner.learn_online);
  EXPECT_EQ(cfg.planner.publish_every, 30);
  EXPECT_EQ(cfg.planner.record, test::kShippedConfig.parent_path() / "x.exp");
  EXPECT_EQ(parse_as_shipped(shipped_config_text(kTraining)).planner.cost_model, CostModelKind::kBinary);
}

TEST(LearnedNavigationConfig, ABadExperienceFileIsRefusedNamingItsLine) {
  const ringlet::test::TempDir dir("navlearn");
  const auto file = dir.path() / "bad.exp";
  {
    std::ofstream out(file);
    out << "ringlet-experiences 1\nframe time_ns duration_s commanded_speed achieved_speed diagonal from to from_left "
           "from_right to_left to_right behind ahead corner_left corner_right\n1 2 three\n";
  }
  const auto cfg = parse_as_shipped(training("cost_model = \"knn\"\nexperiences = \"" + file.string() + "\"", 0));
  try {
    FirmwareStack stack(cfg);
    ADD_FAILURE() << "a bad experience file must be refused";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("planner.experiences: " + file.string() + ":3:"), std::string::npos) << what;
  }
}

// Region changes along the trajectory (sampled as often as the planner runs): what the recorder
// can have seen.
std::size_t region_changes(const std::vector<hal::Pose2>& poses, const planning::MapConfig& m) {
  std::size_t n = 0;
  int last = -1;
  for (const auto& p : poses) {
    const int rx = static_cast<int>(std::floor((p.x - m.origin_x) / m.region_size()));
    const int ry = static_cast<int>(std::floor((p.y - m.origin_y) / m.region_size()));
    const int r = ry * m.regions_x() + rx;
    if (last >= 0 && r != last) ++n;
    last = r;
  }
  return n;
}

TEST(LearnedNavigation, ALockstepMissionRecordsSaneExperiencesAndTheFileRoundTrips) {
  const ringlet::test::TempDir dir("navlearn");
  const auto file = dir.path() / "training.exp";
  const std::string text = training("record = \"" + file.string() + "\"", 0);
  const LearnedRun r = run(text);
  ASSERT_TRUE(r.summary.complete);
  const auto cfg = parse_as_shipped(text);
  const double top = cfg.planner.cost.top_speed;
  const std::size_t changes = region_changes(r.trajectory, cfg.planner.map);
  // One experience per region entered, but for the first region of each leg and the jumps.
  EXPECT_GT(r.experiences.size(), changes * 8 / 10) << changes << " region changes";
  EXPECT_LE(r.experiences.size(), changes + 4);
  std::uint64_t last_frame = 0;
  double progress = 0.0;
  for (const auto& e : r.experiences) {
    EXPECT_GT(e.achieved_speed, 0.0);
    EXPECT_LE(e.achieved_speed, top);
    EXPECT_GE(e.commanded_speed, 0.0);
    EXPECT_LE(e.commanded_speed, top + 1e-9);
    EXPECT_GT(e.duration_s, 0.0);
    EXPECT_GT(e.frame, last_frame);
    EXPECT_EQ(e.time_ns, static_cast<std::int64_t>(e.frame) * cfg.executive.period.count());
    last_frame = e.frame;
    for (const double f : e.features) {
      EXPECT_GE(f, 0.0);
      EXPECT_LE(f, 1.0);
    }
    progress += e.achieved_speed * e.duration_s;
  }
  // Net progress summed over the transitions: no more than the distance driven.
  EXPECT_LE(progress, r.summary.distance_m);
  EXPECT_GT(progress, 0.5 * r.summary.distance_m);
  EXPECT_EQ(planning::load_experiences(file), r.experiences);
  // Recording changes nothing the robot does.
  const LearnedRun plain = run(shipped_config_text(kTraining));
  EXPECT_EQ(plain.summary.trajectory_hash, r.summary.trajectory_hash);
  EXPECT_TRUE(plain.experiences.empty());
}

TEST(LearnedNavigation, OnlineLearningIsBitIdenticalRunToRunAndInsideTheBudget) {
  if (test::kCpuSlowdown >= 40.0) GTEST_SKIP() << "two 60 s missions: native builds only";
  const std::string text =
      training("cost_model = \"knn\"\nlearn_online = true\npublish_every = 20", 60.0);
  const LearnedRun a = run(text);
  const LearnedRun b = run(text);
  EXPECT_GE(a.publishes, 3U) << "the model must have been rebuilt and switched during the run";
  EXPECT_GT(a.experiences.size(), 20U);
  EXPECT_EQ(a.summary.run_hash, b.summary.run_hash);
  EXPECT_EQ(a.summary.trajectory_hash, b.summary.trajectory_hash);
  EXPECT_EQ(a.experiences, b.experiences);
  EXPECT_EQ(a.summary.collisions, 0U);
  EXPECT_EQ(a.planner.overruns, 0U);
  EXPECT_LE(a.planner.model.max(), a.budget);
}

TEST(LearnedNavigation, AModelFromTheTrainingWorldPlansTheWoodsInsideTheBudget) {
  if (test::kCpuSlowdown >= 40.0) GTEST_SKIP() << "whole missions: native builds only";
  const ringlet::test::TempDir dir("navlearn");
  const auto file = dir.path() / "training.exp";
  const LearnedRun trained = run(training("record = \"" + file.string() + "\"", 0));
  ASSERT_GT(trained.experiences.size(), 50U);
  const std::string woods = with_line(shipped_config_text(test::kShippedConfig.parent_path() / "pb_woods.toml"),
                                      "pops_per_slice", "pops_per_slice = 2000\ncost_model = \"knn\"\nexperiences = \"" +
                                                            file.string() + "\"");
  const LearnedRun r = run(with_line(woods, "timeout_s", "timeout_s = 60"));
  EXPECT_EQ(r.summary.collisions, 0U);
  EXPECT_EQ(r.planner.overruns, 0U);
  EXPECT_LE(r.planner.model.max(), r.budget);
  EXPECT_GT(r.planner.runs, 500U);
}

}  // namespace
}  // namespace ringlet::firmware
