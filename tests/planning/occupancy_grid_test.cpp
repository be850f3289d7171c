#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "ringlet/planning/occupancy_grid.hpp"

namespace ringlet::planning {
namespace {

MapConfig small_map() {
  MapConfig c;
  c.origin_x = -2.0;
  c.origin_y = -1.0;
  c.resolution = 0.5;
  c.width_cells = 8;
  c.height_cells = 4;
  c.region_cells = 2;
  return c;
}

TEST(MapConfig, NamesWhatIsWrong) {
  EXPECT_EQ(small_map().validate(), "");
  MapConfig c = small_map();
  c.resolution = 0.0;
  EXPECT_NE(c.validate().find("resolution"), std::string::npos);
  c = small_map();
  c.region_cells = 3;
  EXPECT_NE(c.validate().find("multiples of region_cells"), std::string::npos);
  c = small_map();
  c.width_cells = -1;
  EXPECT_NE(c.validate().find("width_cells"), std::string::npos);
  c = small_map();
  c.origin_x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(c.validate().find("origin_x"), std::string::npos);
}

TEST(OccupancyGrid, AnObstacleMarksAFreeCellAndAnOccupiedCellStaysOccupied) {
  OccupancyGrid m(small_map());
  EXPECT_TRUE(m.mark(-1.9, -0.9));   // cell (0, 0), region 0
  EXPECT_FALSE(m.mark(-1.6, -0.6));  // the same cell: no effect
  EXPECT_TRUE(m.mark(-1.4, -0.9));   // cell (1, 0), still region 0
  EXPECT_TRUE(m.mark(1.9, 0.9));     // cell (7, 3), region 3 + 4 = 7
  EXPECT_FALSE(m.mark(2.0, 0.0));    // on the far edge: outside
  EXPECT_FALSE(m.mark(std::numeric_limits<double>::quiet_NaN(), 0.0));
  EXPECT_TRUE(m.occupied(0, 0));
  EXPECT_TRUE(m.occupied(1, 0));
  EXPECT_FALSE(m.occupied(0, 1));
  EXPECT_EQ(m.occupied_cells(), 3);
  EXPECT_EQ(m.region_count(0), 2);
  EXPECT_EQ(m.region_count(7), 1);
  EXPECT_EQ(m.region_count(1), 0);
  // Each changed region once, in the order it changed.
  ASSERT_EQ(m.changed_regions().size(), 2U);
  EXPECT_EQ(m.changed_regions()[0], 0);
  EXPECT_EQ(m.changed_regions()[1], 7);
  m.clear_changes();
  EXPECT_TRUE(m.changed_regions().empty());
  EXPECT_TRUE(m.mark(-1.9, -0.4));  // cell (0, 1), region 0 again
  ASSERT_EQ(m.changed_regions().size(), 1U);
  EXPECT_EQ(m.changed_regions()[0], 0);
}

TEST(OccupancyGrid, RegionCentresAreTheWaypoints) {
  OccupancyGrid m(small_map());
  const hal::Pose2 c0 = m.region_centre(0);
  EXPECT_DOUBLE_EQ(c0.x, -1.5);
  EXPECT_DOUBLE_EQ(c0.y, -0.5);
  const hal::Pose2 c7 = m.region_centre(7);
  EXPECT_DOUBLE_EQ(c7.x, 1.5);
  EXPECT_DOUBLE_EQ(c7.y, 0.5);
  EXPECT_EQ(m.region_at(c7.x, c7.y), 7);
  EXPECT_EQ(m.region_at(5.0, 0.0), -1);
}

TEST(OccupancyGrid, IntegratesTheValidBeamsOfAScanThroughThePose) {
  MapConfig c;
  c.origin_x = -5.0;
  c.origin_y = -5.0;
  c.resolution = 0.1;
  c.width_cells = 100;
  c.height_cells = 100;
  c.region_cells = 10;
  OccupancyGrid m(c);
  hal::LaserScan scan;
  scan.beam_count = 3;
  scan.angle_min = -std::numbers::pi / 2;
  scan.angle_increment = std::numbers::pi / 2;
  scan.max_range = 4.0;
  scan.range = {2.05f, 3.0f, 1.05f};
  scan.valid = {true, false, true};
  // At (1, 1) facing +x (theta = π/2): beam 0 (−90°, to the robot's left) looks along +y, beam 2
  // (+90°, to its right) along −y.
  const hal::Pose2 pose{1.0, 1.0, std::numbers::pi / 2};
  EXPECT_EQ(m.integrate(scan, pose), 2);
  int cx = 0, cy = 0;
  ASSERT_TRUE(m.cell_of(1.0, 3.05, cx, cy));
  EXPECT_TRUE(m.occupied(cx, cy));
  ASSERT_TRUE(m.cell_of(1.0, -0.05, cx, cy));
  EXPECT_TRUE(m.occupied(cx, cy));
  ASSERT_TRUE(m.cell_of(4.0, 1.0, cx, cy));
  EXPECT_FALSE(m.occupied(cx, cy));  // the invalid beam saw nothing: phi marks nothing
  EXPECT_EQ(m.occupied_cells(), 2);
}

}  // namespace
}  // namespace ringlet::planning
