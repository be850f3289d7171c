// The hybrid controller in the cycle (Powers & Balch): the planner task (D* Lite over the laser's
// occupancy grid) and the arbiter task (arc voting) under the Navigate machine, with the Safety
// machine keeping the last word. Lockstep: every slice inside its budget on the modelled cost,
// the shipped navigation missions complete without collisions, and a half-computed plan is never
// posted.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <string_view>

#include "firmware_test_support.hpp"
#include "ringlet/behaviour/machines/navigate.hpp"
#include "ringlet/behaviour/machines/safety.hpp"
#include "ringlet/firmware/mission_report.hpp"
#include "ringlet/firmware/mission_runner.hpp"
#include "ringlet/firmware/stack.hpp"
#include "ringlet/firmware/task_registry.hpp"
#include "ringlet/firmware/tasks/planner_task.hpp"
#include "ringlet/hal/virtual_clock.hpp"

namespace ringlet::firmware {
namespace {

using test::parse_as_shipped;
using test::shipped_config_text;
using test::with_line;

const std::filesystem::path kNavConfig = test::kShippedConfig.parent_path() / "courtyard_navigate.toml";

struct NavRun {
  MissionSummary summary;
  executive::TaskStats planner{}, arbiter{};
  hal::Nanos planner_budget{0}, arbiter_budget{0};
  std::uint64_t overruns = 0;
  std::uint64_t plans_posted = 0, half_plans = 0;
};

NavRun run(const std::string& text) {
  const auto cfg = parse_as_shipped(text);
  FirmwareStack stack(cfg);
  NavRun r;
  stack.whiteboard().subscribe<wb::Plan>([&r](const wb::Plan& p) {
    ++r.plans_posted;
    // A posted plan is either a finished one or the last finished one kept during a repair.
    if (p.has_plan && (p.path_count < 1 || !std::isfinite(p.expected_s))) ++r.half_plans;
  });
  std::atomic<bool> interrupt{false};
  std::ostringstream log;
  const auto outcome = run_mission(stack, cfg.mission.timeout_s, interrupt, log);
  r.summary = summarize(stack, outcome, stack.executive().failsafe_triggered() || outcome.watchdog_fired);
  const auto& tasks = stack.executive().tasks();
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    r.overruns += stack.executive().task_stats()[i].overruns;
    if (tasks[i].spec.name == "planner") {
      r.planner = stack.executive().task_stats()[i];
      r.planner_budget = tasks[i].spec.budget;
    }
    if (tasks[i].spec.name == "arbiter") {
      r.arbiter = stack.executive().task_stats()[i];
      r.arbiter_budget = tasks[i].spec.budget;
    }
  }
  return r;
}

TEST(Navigation, NoTaskWritesMotionCommandSoSafetyKeepsTheLastWordWhateverTheTaskOrder) {
  // Only machines write MotionCommand, and the Safety machine runs last in every turn: no row of
  // any task table can post after it.
  const TaskRegistry registry = production_tasks();
  for (const RegisteredTask& t : registry.tasks()) {
    for (const std::string_view type : t.declaration->provides_types) EXPECT_NE(type, "MotionCommand") << t.declaration->name;
  }
}

TEST(Navigation, SafetysStopHoldsOverTheArbitersProposalInTheSameTurn) {
  wb::Whiteboard board;
  behaviour::machines::Navigate navigate(board);
  behaviour::machines::Safety safety(board, 0.9, 1.2, 300);
  hal::VirtualClock clock;
  behaviour::llfsm::Schedule schedule(clock);
  schedule.add(navigate);
  schedule.add(safety, 2);
  schedule.start();
  wb::MissionGoals goals{};
  goals.count = 1;
  goals.x[0] = 5.0;
  goals.y[0] = 5.0;
  goals.tolerance = 0.3;
  board.post(goals);
  board.post(wb::Pose{0.0, 0.0, 0.0, true});
  wb::Plan plan{};
  plan.status = wb::PlanStatus::kReady;
  plan.has_plan = true;
  plan.goal_x = 5.0;
  plan.goal_y = 5.0;
  plan.waypoint_x = 1.0;
  plan.waypoint_y = 1.0;
  board.post(plan);
  wb::ArbiterCommand arbiter{};
  arbiter.valid = true;
  arbiter.curvature = 0.5;
  arbiter.velocity = 1.0;
  board.post(arbiter);
  // The way is clear for long enough: Safety releases, Navigate drives the arbiter's arc.
  wb::LaserSummary clear{};
  clear.nearest_range = 5.0;
  clear.valid_beams = 181;
  board.post(clear);
  hal::Nanos now{0};
  for (int turn = 0; turn < 60; ++turn, now += hal::Nanos{10'000'000}) schedule.run_turn(now);
  ASSERT_EQ(navigate.current_state_name(), "Follow");
  ASSERT_EQ(safety.current_state_name(), "Clear");
  EXPECT_FALSE(board.get<wb::MotionCommand>().stop);
  EXPECT_DOUBLE_EQ(board.get<wb::MotionCommand>().velocity, 1.0);
  // Something within the stop range: the same turn ends with the stop, though Navigate still
  // copies the arbiter's full-speed proposal earlier in that turn.
  wb::LaserSummary close = clear;
  close.nearest_range = 0.5;
  board.post(close);
  schedule.run_turn(now);
  EXPECT_EQ(safety.current_state_name(), "Stopped");
  EXPECT_TRUE(board.get<wb::MotionCommand>().stop);
  EXPECT_EQ(board.get<wb::MotionCommand>().velocity, 0.0);
  // The arbiter posting again (its task after fsm in the table) changes nothing it could drive.
  board.post(arbiter);
  EXPECT_TRUE(board.get<wb::MotionCommand>().stop);
}

TEST(Navigation, APlanIsPostedOnlyWhenItsSearchHasFinished) {
  auto cfg = parse_as_shipped(shipped_config_text(kNavConfig));
  cfg.planner.pops_per_slice = 3;  // a slice far too small for the courtyard: many activations
  wb::Whiteboard board;
  PlannerTask planner(cfg.planner, board, false);
  board.post(wb::Pose{1.5, 1.5, 0.0, true});
  wb::MissionStatus mission{};
  mission.goal_count = 1;
  mission.target_x = 17.5;
  mission.target_y = 11.5;
  board.post(mission);
  executive::TaskContext ctx;
  int searching = 0;
  for (int i = 0; i < 1000; ++i) {
    planner.run(ctx);
    const wb::Plan p = board.get<wb::Plan>();
    if (p.status == wb::PlanStatus::kSearching) {
      ++searching;
      EXPECT_FALSE(p.has_plan) << "activation " << i << ": no plan was ever ready, none may be posted";
      EXPECT_LE(planner.modelled_cost(), PlannerTask::kBaseCost + 3 * PlannerTask::kCostPerPop);
      continue;
    }
    ASSERT_EQ(p.status, wb::PlanStatus::kReady);
    ASSERT_TRUE(p.has_plan);
    ASSERT_GE(p.path_count, 2);
    // The waypoint: the centre of the next region, one region (1 m) away, 8-connected.
    EXPECT_DOUBLE_EQ(p.waypoint_x, p.path_x[1]);
    EXPECT_LE(std::abs(p.waypoint_x - 1.5), 1.0 + 1e-9);
    EXPECT_LE(std::abs(p.waypoint_y - 1.5), 1.0 + 1e-9);
    EXPECT_GT(p.expected_s, std::hypot(17.5 - 1.5, 11.5 - 1.5) / cfg.planner.cost.top_speed - 1.0);
    break;
  }
  EXPECT_GT(searching, 10) << "the search must have been sliced";
}

TEST(Navigation, RobotsVisionSeesEnterTheMapAsLaserHitsDo) {
  auto cfg = parse_as_shipped(shipped_config_text(kNavConfig));
  wb::Whiteboard board;
  PlannerTask planner(cfg.planner, board, false);
  board.post(wb::Pose{5.0, 5.0, std::numbers::pi / 2, true});  // facing +x
  executive::TaskContext ctx;
  planner.run(ctx);
  EXPECT_EQ(planner.map().occupied_cells(), 0);
  wb::RobotDetections robots{};
  robots.count = 1;
  robots.foot_x[0] = 2.0;  // 2 m ahead, 1 m to the left: world (7, 6)
  robots.foot_y[0] = 1.0;
  board.post(robots);
  planner.run(ctx);
  int cx = 0, cy = 0;
  ASSERT_TRUE(planner.map().cell_of(7.0, 6.0, cx, cy));
  EXPECT_TRUE(planner.map().occupied(cx, cy));
  EXPECT_EQ(planner.map().occupied_cells(), 1);
  const wb::Plan plan = board.get<wb::Plan>();
  ASSERT_EQ(plan.new_cell_count, 1);
  EXPECT_EQ(plan.new_cells[0], static_cast<std::uint32_t>(cy * cfg.planner.map.width_cells + cx));
  planner.run(ctx);  // the same detections are not marked twice (nor counted as new)
  EXPECT_EQ(board.get<wb::Plan>().new_cell_count, 0);
}

// The shipped navigation missions, whole: the courtyard and Powers & Balch's three worlds.
struct NavMission {
  const char* config;
  std::size_t goals;
};
class NavigationMission : public ::testing::TestWithParam<NavMission> {};

TEST_P(NavigationMission, CompletesWithoutCollisionsEverySliceInsideItsBudget) {
  const NavMission m = GetParam();
  if (test::kCpuSlowdown >= 40.0 && std::string_view(m.config) != "courtyard_navigate.toml") {
    // Under qemu a whole world takes a minute; the same runs are bit-identical there
    // (GoldenRun.Pb*: the first 30 s of each, hashes equal on both).
    GTEST_SKIP() << m.config << ": the whole mission is run on native builds";
  }
  const NavRun r = run(shipped_config_text(test::kShippedConfig.parent_path() / m.config));
  EXPECT_TRUE(r.summary.complete);
  EXPECT_EQ(r.summary.goals_reached, m.goals);
  EXPECT_EQ(r.summary.collisions, 0U);
  EXPECT_EQ(r.overruns, 0U);
  EXPECT_EQ(r.half_plans, 0U);
  EXPECT_GT(r.plans_posted, 100U);
  ASSERT_GT(r.planner.runs, 0U);
  ASSERT_GT(r.arbiter.runs, 0U);
  // The deterministic timing: the modelled cost of every activation (lockstep judges on it).
  EXPECT_LE(r.planner.model.max(), r.planner_budget);
  EXPECT_LE(r.arbiter.model.max(), r.arbiter_budget);
  EXPECT_EQ(r.planner.overruns, 0U);
  EXPECT_EQ(r.arbiter.overruns, 0U);
}

INSTANTIATE_TEST_SUITE_P(Shipped, NavigationMission,
                         ::testing::Values(NavMission{"courtyard_navigate.toml", 7}, NavMission{"pb_training.toml", 4},
                                           NavMission{"pb_test.toml", 4}, NavMission{"pb_woods.toml", 1}),
                         [](const auto& param_info) {
                           std::string name = param_info.param.config;
                           name = name.substr(0, name.find('.'));
                           std::erase(name, '_');
                           return name;
                         });

}  // namespace
}  // namespace ringlet::firmware
