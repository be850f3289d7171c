#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ringlet/planning/region_graph.hpp"

namespace ringlet::planning {
namespace {

MapConfig map_3x3_regions() {
  MapConfig c;
  c.resolution = 0.5;
  c.width_cells = 6;
  c.height_cells = 6;
  c.region_cells = 2;  // regions of 1 m: 3 × 3 of them
  return c;
}

/// Fills region (rx, ry) with `n` occupied cells.
void occupy(OccupancyGrid& m, int rx, int ry, int n) {
  for (int i = 0; i < n; ++i) m.mark(rx * 1.0 + 0.25 + 0.5 * (i % 2), ry * 1.0 + 0.25 + 0.5 * (i / 2));
}

TEST(BinaryCostModel, TimeIsDistanceOverTopSpeedUnlessARegionIsTooFull) {
  OccupancyGrid m(map_3x3_regions());
  const BinaryCostModel model({.max_occupied = 1, .top_speed = 2.0});
  const RegionGraph g(m, model);
  EXPECT_EQ(g.width(), 3);
  EXPECT_EQ(g.height(), 3);
  EXPECT_EQ(g.step_cost(g.vertex(0, 0), 0), 500'000'000);    // 1 m at 2 m/s, in ns
  EXPECT_EQ(g.step_cost(g.vertex(0, 0), 1), 707'106'781);    // diagonal
  EXPECT_EQ(g.step_cost(g.vertex(0, 0), 4), kInfiniteCost);  // off the grid
  EXPECT_EQ(g.min_step_cost(), 500'000'000);
  EXPECT_EQ(g.min_diagonal_cost(), 707'106'781);
  occupy(m, 1, 0, 1);  // at the threshold: still passable
  EXPECT_EQ(g.step_cost(g.vertex(0, 0), 0), 500'000'000);
  occupy(m, 1, 0, 2);  // over it: impassable both ways
  EXPECT_EQ(m.region_count(1), 2);
  EXPECT_EQ(g.step_cost(g.vertex(0, 0), 0), kInfiniteCost);
  EXPECT_EQ(g.step_cost(g.vertex(1, 0), 4), kInfiniteCost);
  EXPECT_EQ(g.step_cost(g.vertex(1, 0), 2), kInfiniteCost);  // out of a full region too
}

TEST(RegionGraph, NoCornerCuttingPastABlockedSide) {
  OccupancyGrid m(map_3x3_regions());
  const BinaryCostModel model({.max_occupied = 0, .top_speed = 1.0});
  const RegionGraph g(m, model);
  occupy(m, 1, 0, 1);  // the region to the right of (0, 0)
  // (0, 0) → (1, 1) passes the corner of (1, 0): refused; (0, 1) → (1, 2) does not touch it.
  EXPECT_EQ(g.step_cost(g.vertex(0, 0), 1), kInfiniteCost);
  EXPECT_EQ(g.step_cost(g.vertex(1, 1), 5), kInfiniteCost);
  EXPECT_EQ(g.step_cost(g.vertex(0, 1), 1), 1'414'213'562);
  EXPECT_EQ(g.step_cost(g.vertex(0, 0), 2), 1'000'000'000);
}

TEST(RegionGraph, TheRobotsOwnRegionNeverKeepsItIn) {
  OccupancyGrid m(map_3x3_regions());
  const BinaryCostModel model({.max_occupied = 0, .top_speed = 1.0});
  RegionGraph g(m, model);
  occupy(m, 1, 1, 1);
  EXPECT_EQ(g.step_cost(g.vertex(1, 1), 0), kInfiniteCost);
  g.set_robot_region(g.vertex(1, 1));
  EXPECT_EQ(g.step_cost(g.vertex(1, 1), 0), 1'000'000'000);  // out of it: allowed
  EXPECT_EQ(g.step_cost(g.vertex(0, 1), 0), kInfiniteCost);  // into it: still full
}

class OddModel final : public CostModel {
 public:
  explicit OddModel(double s) : s_(s) {}
  [[nodiscard]] double expected_speed(const RegionTransition& t) const noexcept override {
    return t.map != nullptr && t.distance > 0.0 ? s_ : 0.0;
  }
  [[nodiscard]] double top_speed() const noexcept override { return 1.0; }

 private:
  double s_;
};

TEST(RegionGraph, AModelFasterThanTopSpeedIsClampedAndNaNIsImpassable) {
  OccupancyGrid m(map_3x3_regions());
  const OddModel fast(5.0), nan(std::numeric_limits<double>::quiet_NaN()), slow(0.25);
  EXPECT_EQ(RegionGraph(m, fast).step_cost(0, 0), 1'000'000'000);  // clamped: the heuristic stays admissible
  EXPECT_EQ(RegionGraph(m, nan).step_cost(0, 0), kInfiniteCost);
  EXPECT_EQ(RegionGraph(m, slow).step_cost(0, 0), 4'000'000'000);
}

TEST(BinaryCostModel, ParamsNameWhatIsWrong) {
  EXPECT_EQ((BinaryCostModel::Params{}).validate(), "");
  EXPECT_NE((BinaryCostModel::Params{.max_occupied = -1}).validate().find("max_occupied"), std::string::npos);
  EXPECT_NE((BinaryCostModel::Params{.top_speed = 0.0}).validate().find("top_speed"), std::string::npos);
}

}  // namespace
}  // namespace ringlet::planning
