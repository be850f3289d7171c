// The planner's prior map ([planner] prior_map): the simulated world on the planner's grid
// (sim_world_map, ringlet-world-map), which cells it marks, the errors of a bad or mis-sized file,
// and what it is for: with the obstacles known from the start, as in Powers & Balch's Fig. 3, a
// model learned in the training world plans down the middle of the wide path in the woods and
// arrives sooner than the binary model, which hugs the wood's edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "firmware_test_support.hpp"
#include "ringlet/firmware/backend_factory.hpp"
#include "ringlet/firmware/mission_report.hpp"
#include "ringlet/firmware/mission_runner.hpp"
#include "ringlet/firmware/stack.hpp"
#include "ringlet/firmware/tasks/planner_task.hpp"
#include "temp_dir.hpp"

namespace ringlet::firmware {
namespace {

using test::parse_as_shipped;
using test::shipped_config_text;
using test::with_line;

const std::filesystem::path kWoods = test::kShippedConfig.parent_path() / "pb_woods.toml";
const std::filesystem::path kTraining = test::kShippedConfig.parent_path() / "pb_training.toml";

/// `text` with `lines` added to [planner].
std::string with_planner(const std::string& text, const std::string& lines) {
  return with_line(text, "pops_per_slice", "pops_per_slice = 2000\n" + lines);
}

void write_map(const std::filesystem::path& file, const planning::MovingAiMap& m) {
  std::ofstream out(file);
  planning::write_movingai_map(out, m);
}

const PlannerTask& planner_of(const FirmwareStack& stack) {
  const auto& tasks = stack.executive().tasks();
  for (const auto& t : tasks) {
    if (t.spec.name == "planner") return *static_cast<const PlannerTask*>(t.task);
  }
  throw std::runtime_error("no planner task");
}

std::string stack_error(const std::string& text) {
  try {
    const FirmwareStack stack(parse_as_shipped(text));
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(PriorMap, TheWorldOnThePlannersGridNorthRowFirst) {
  const planning::MovingAiMap m = sim_world_map(parse_as_shipped(shipped_config_text(kWoods)));
  ASSERT_EQ(m.width, 128);
  ASSERT_EQ(m.height, 144);
  const auto cell = [&](double x, double y) {  // the .map's row 0 is the north edge (y = 36 m)
    const int cx = static_cast<int>(x / 0.25), cy = static_cast<int>(y / 0.25);
    return m.terrain[static_cast<std::size_t>((m.height - 1 - cy) * m.width + cx)];
  };
  EXPECT_EQ(cell(6.65, 28.37), '@');  // pb_woods.world's first tree: circle 6.65 28.37 0.15
  EXPECT_EQ(cell(19.0, 1.6), '.');    // the start, in the southern clearing
  EXPECT_EQ(cell(26.0, 18.0), '.');   // the wide path
  std::size_t blocked = 0;
  for (const char c : m.terrain) blocked += c == '@' ? 1U : 0U;
  EXPECT_GT(blocked, 330U);  // at least a cell per tree
  EXPECT_LT(blocked, m.terrain.size() / 4);
}

TEST(PriorMap, NotASimulatedRobotHasNoWorldToMap) {
  const std::string can = with_line(shipped_config_text(), "backend", "backend = \"can\"");
  try {
    (void)sim_world_map(parse_as_shipped(can));
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("robot.backend: \"can\", not \"sim\""), std::string::npos) << e.what();
  }
}

TEST(PriorMap, ItsBlockedCellsAreKnownBeforeTheFirstScan) {
  const ringlet::test::TempDir dir("prior_map");
  const auto file = dir.path() / "woods.map";
  const std::string woods = shipped_config_text(kWoods);
  const planning::MovingAiMap m = sim_world_map(parse_as_shipped(woods));
  write_map(file, m);
  std::size_t blocked = 0;
  for (const char c : m.terrain) blocked += c == '@' ? 1U : 0U;

  const FirmwareStack with(parse_as_shipped(with_planner(woods, "prior_map = \"" + file.string() + "\"")));
  EXPECT_EQ(static_cast<std::size_t>(planner_of(with).map().occupied_cells()), blocked);
  const FirmwareStack without(parse_as_shipped(woods));
  EXPECT_EQ(planner_of(without).map().occupied_cells(), 0);
}

TEST(PriorMap, AFileOfAnotherSizeOrAMalformedOneIsRefusedWithItsPlace) {
  const ringlet::test::TempDir dir("prior_map_bad");
  const auto small = dir.path() / "small.map";
  planning::MovingAiMap m;
  m.width = 4;
  m.height = 4;
  m.terrain.assign(16, '.');
  write_map(small, m);
  const std::string woods = shipped_config_text(kWoods);
  const std::string wrong = stack_error(with_planner(woods, "prior_map = \"" + small.string() + "\""));
  EXPECT_EQ(wrong.rfind(test::kShippedConfig.string() + ":", 0), 0U) << wrong;  // file:line:col first
  EXPECT_NE(wrong.find("planner.prior_map: " + small.string() + " is 4 x 4 cells, the planner's grid 128 x 144"),
            std::string::npos)
      << wrong;

  const auto bad = dir.path() / "bad.map";
  std::ofstream(bad) << "type octile\nheight 2\nwidth 2\nmap\n..\n.x\n";
  const std::string malformed = stack_error(with_planner(woods, "prior_map = \"" + bad.string() + "\""));
  EXPECT_NE(malformed.find("planner.prior_map: "), std::string::npos) << malformed;
  EXPECT_NE(malformed.find(bad.string() + ":6"), std::string::npos) << malformed;  // the row with 'x'
  EXPECT_NE(malformed.find("unknown terrain 'x'"), std::string::npos) << malformed;
}

struct WoodsRun {
  MissionSummary summary;
  double median_x_midway = 0.0;  // the median x while 12 m < y < 24 m: the wide path is x 24-28
};

WoodsRun run_woods(const std::string& text) {
  const auto cfg = parse_as_shipped(text);
  FirmwareStack stack(cfg);
  const auto outcome = test::run_to_end(stack, cfg);
  WoodsRun r;
  r.summary = summarize(stack, outcome, stack.executive().failsafe_triggered() || outcome.watchdog_fired);
  std::vector<double> xs;
  for (const hal::Pose2& p : stack.telemetry().trajectory()) {
    if (p.y > 12.0 && p.y < 24.0) xs.push_back(p.x);
  }
  if (!xs.empty()) {
    std::nth_element(xs.begin(), xs.begin() + static_cast<std::ptrdiff_t>(xs.size() / 2), xs.end());
    r.median_x_midway = xs[xs.size() / 2];
  }
  return r;
}

TEST(PriorMap, WithItALearnedModelKeepsToTheMiddleOfTheWidePathAndArrivesSooner) {
  if (test::kCpuSlowdown >= 40.0) GTEST_SKIP() << "whole missions: native builds only";
  const ringlet::test::TempDir dir("prior_map_woods");
  const auto experiences = dir.path() / "training.exp";
  const auto map = dir.path() / "woods.map";
  {  // one training mission with the binary model, its experiences recorded
    const auto cfg = parse_as_shipped(with_planner(shipped_config_text(kTraining), "record = \"" + experiences.string() + "\""));
    FirmwareStack stack(cfg);
    const auto outcome = test::run_to_end(stack, cfg);
    ASSERT_TRUE(outcome.experiences_error.empty()) << outcome.experiences_error;
  }
  const std::string woods = shipped_config_text(kWoods);
  write_map(map, sim_world_map(parse_as_shipped(woods)));
  const std::string prior = "prior_map = \"" + map.string() + "\"";
  const WoodsRun binary = run_woods(with_planner(woods, prior));
  const WoodsRun learned =
      run_woods(with_planner(woods, prior + "\ncost_model = \"knn\"\nexperiences = \"" + experiences.string() + "\""));
  ASSERT_TRUE(binary.summary.complete);
  ASSERT_TRUE(learned.summary.complete);
  EXPECT_EQ(binary.summary.collisions, 0U);
  EXPECT_EQ(learned.summary.collisions, 0U);
  // With every tree's footprint known, the binary model closes most of the wood too (more than
  // max_occupied cells a region) and follows the path along the wood's edge, where Slow for
  // Congested Areas holds it back; the learned model, which knows regions beside trees are slow,
  // keeps to the middle of the path.
  EXPECT_GT(learned.median_x_midway, 24.0) << "the learned model drives along the wide path";
  EXPECT_GT(learned.median_x_midway, binary.median_x_midway + 0.5) << "the learned model keeps off the wood's edge";
  std::printf("woods with the prior map: binary %.2f s (median x %.2f m midway), learned %.2f s (%.2f m)\n",
              binary.summary.mission_seconds, binary.median_x_midway, learned.summary.mission_seconds,
              learned.median_x_midway);
  EXPECT_LT(learned.summary.mission_seconds, 0.9 * binary.summary.mission_seconds)
      << "learned " << learned.summary.mission_seconds << " s, binary " << binary.summary.mission_seconds << " s";
}

}  // namespace
}  // namespace ringlet::firmware
