// The shipped MovingAI maps: D* Lite and A* find every scenario's optimal length (computed by
// planning/maps/make_maps.py with networkx, not by these planners), and when obstacles are found
// while driving, D* Lite needs at least 10 times fewer expansions than A* from scratch on a
// 200 × 200 map (expansions are deterministic: the figure in the README comes from the bench).
#include <gtest/gtest.h>

#include <cmath>

#include "bench_runs.hpp"

namespace ringlet::planning {
namespace {

const std::filesystem::path kMaps = RINGLET_PLANNING_MAPS_DIR;

class ShippedMap : public ::testing::TestWithParam<const char*> {};

TEST_P(ShippedMap, BothPlannersFindTheScenarioOptimalLengths) {
  const std::string name = GetParam();
  const MovingAiMap map = read_movingai_map(kMaps / (name + ".map"));
  const auto problems = read_movingai_scen(kMaps / (name + ".map.scen"));
  ASSERT_GE(problems.size(), 30U);
  for (const auto& r : bench::check_scenarios(map, problems)) {
    EXPECT_NEAR(r.dstar, r.optimal, 1e-6) << name << ".map.scen:" << r.line;
    EXPECT_NEAR(r.astar, r.optimal, 1e-6) << name << ".map.scen:" << r.line;
  }
}

INSTANTIATE_TEST_SUITE_P(Maps, ShippedMap, ::testing::Values("rooms200", "forest200", "maze65"));

TEST(PlanBench, DStarLiteNeedsTenTimesFewerExpansionsThanRepeatedAStarOnA200Grid) {
  const MovingAiMap map = read_movingai_map(kMaps / "rooms200.map");
  auto problems = read_movingai_scen(kMaps / "rooms200.map.scen");
  problems.resize(10);
  std::int64_t d = 0, a = 0;
  for (const auto& p : problems) {
    const bench::ReplanRow r = bench::replan(map, p, {});
    EXPECT_TRUE(r.reached) << "line " << r.line;
    EXPECT_GT(r.replans, 0);
    EXPECT_EQ(r.trajectory.front(), map.width * p.start_y + p.start_x);
    EXPECT_EQ(r.trajectory.back(), map.width * p.goal_y + p.goal_x);
    EXPECT_GE(r.travelled + 1e-9, p.optimal);  // discovering obstacles never makes the way shorter
    d += r.dstar_expansions;
    a += r.astar_expansions;
  }
  EXPECT_GE(static_cast<double>(a) / static_cast<double>(d), 10.0) << "D* Lite " << d << ", A* " << a;
}

}  // namespace
}  // namespace ringlet::planning
