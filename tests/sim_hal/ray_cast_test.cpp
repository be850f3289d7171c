// Ray casting and disc overlap against hand-computed geometry, and the laser scan SimRobot builds
// from them.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "ringlet/sim_hal/collision.hpp"
#include "ringlet/sim_hal/sim_robot.hpp"
#include "sim_test_support.hpp"

namespace ringlet::sim_hal {
namespace {

using test::box_world;
constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// 10 m x 10 m with a circle of radius 1 at (5, 8) and a 2 m square at (1..3, 7..9).
World test_world() {
  World world = box_world(10.0, 10.0, {5.0, 5.0, 0.0});
  world.circles.push_back({{5.0, 8.0}, 1.0});
  world.polygons.push_back({{{1.0, 7.0}, {3.0, 7.0}, {3.0, 9.0}, {1.0, 9.0}}});
  return world;
}

TEST(SimRayCast, CircleStraightAhead) {
  EXPECT_NEAR(cast_ray(test_world(), {5.0, 5.0}, 0.0, 8.0), 2.0, 1e-12);
}

TEST(SimRayCast, CircleGrazedOffCentre) {
  // From (5.6, 5) going north the ray meets the rim where (x - 5)^2 + (y - 8)^2 = 1, x = 5.6.
  EXPECT_NEAR(cast_ray(test_world(), {5.6, 5.0}, 0.0, 8.0), 3.0 - 0.8, 1e-12);
}

TEST(SimRayCast, WallsInEveryDirection) {
  const World world = test_world();
  EXPECT_NEAR(cast_ray(world, {5.0, 5.0}, kPi / 2.0, 8.0), 5.0, 1e-12);   // east
  EXPECT_NEAR(cast_ray(world, {5.0, 5.0}, kPi, 8.0), 5.0, 1e-12);         // south
  EXPECT_NEAR(cast_ray(world, {5.0, 5.0}, -kPi / 2.0, 8.0), 5.0, 1e-12);  // west
  EXPECT_NEAR(cast_ray(world, {5.0, 5.0}, 3.0 * kPi / 4.0, 8.0), 5.0 * std::sqrt(2.0), 1e-12);  // into a corner
  EXPECT_NEAR(cast_ray(world, {7.0, 2.0}, kPi / 4.0, 20.0), 3.0 * std::sqrt(2.0), 1e-12);       // up-right
}

TEST(SimRayCast, PolygonEdges) {
  const World world = test_world();
  EXPECT_NEAR(cast_ray(world, {2.0, 5.0}, 0.0, 8.0), 2.0, 1e-12);        // bottom edge, from below
  EXPECT_NEAR(cast_ray(world, {4.0, 7.5}, -kPi / 2.0, 8.0), 1.0, 1e-12); // right edge, from the east
  EXPECT_NEAR(cast_ray(world, {0.5, 8.0}, kPi / 2.0, 8.0), 0.5, 1e-12);  // left edge, from the west
  EXPECT_NEAR(cast_ray(world, {0.5, 8.0}, -kPi / 2.0, 8.0), 0.5, 1e-12); // and the wall behind
}

TEST(SimRayCast, NearestObstacleWins) {
  World world = test_world();
  world.circles.push_back({{5.0, 6.5}, 0.25});  // in front of the big circle
  EXPECT_NEAR(cast_ray(world, {5.0, 5.0}, 0.0, 8.0), 1.25, 1e-12);
}

TEST(SimRayCast, NothingWithinRangeIsInfinity) {
  const World world = test_world();
  EXPECT_EQ(cast_ray(world, {5.0, 5.0}, kPi / 2.0, 4.0), kInf);  // wall at 5 m, range 4 m
  EXPECT_EQ(cast_ray(world, {5.0, 5.0}, 0.0, 1.999), kInf);
  // A hit exactly at the maximum range still counts.
  EXPECT_NEAR(cast_ray(world, {5.0, 5.0}, kPi, 5.0), 5.0, 1e-12);
}

TEST(SimRayCast, ObstacleBehindIsNotHit) {
  World world = box_world(100.0, 100.0, {50.0, 50.0, 0.0});
  world.circles.push_back({{50.0, 45.0}, 1.0});
  EXPECT_NEAR(cast_ray(world, {50.0, 50.0}, 0.0, 100.0), 50.0, 1e-12);  // the wall, not the circle
}

TEST(SimDiscCollides, AgainstCirclesPolygonsAndWalls) {
  const World world = test_world();
  EXPECT_FALSE(disc_collides(world, {5.0, 5.0}, 0.25));
  EXPECT_FALSE(disc_collides(world, {5.0, 6.75}, 0.25));  // exactly touching is not overlapping
  EXPECT_TRUE(disc_collides(world, {5.0, 6.76}, 0.25));
  EXPECT_TRUE(disc_collides(world, {2.0, 6.8}, 0.25));    // near the polygon's bottom edge
  EXPECT_TRUE(disc_collides(world, {3.1, 9.1}, 0.25));    // near a corner
  EXPECT_FALSE(disc_collides(world, {3.2, 9.2}, 0.25));   // diagonal clearance 0.28 > 0.25
  EXPECT_TRUE(disc_collides(world, {0.2, 5.0}, 0.25));    // through the west wall
  EXPECT_TRUE(disc_collides(world, {5.0, 9.9}, 0.25));    // through the north wall
  EXPECT_FALSE(disc_collides(world, {0.25, 0.25}, 0.25)); // snug in the corner
}

TEST(SimDiscCollides, DiscDeepInsideABigPolygon) {
  World world = box_world(20.0, 20.0, {1.0, 1.0, 0.0});
  world.polygons.push_back({{{5.0, 5.0}, {15.0, 5.0}, {15.0, 15.0}, {5.0, 15.0}}});
  EXPECT_TRUE(disc_collides(world, {10.0, 10.0}, 0.25));  // no edge near, but inside
  EXPECT_FALSE(disc_collides(world, {3.0, 10.0}, 0.25));
}

TEST(SimRayCast, LaserScanFromSimRobot) {
  SimConfig config;
  config.laser_beams = 181;  // one beam per degree over a half circle
  config.laser_fov = kPi;
  config.laser_range = 4.5;
  SimRobot robot(test_world(), config);
  hal::SensorFrame frame;
  ASSERT_TRUE(robot.sensors().read(frame));
  const hal::LaserScan& scan = frame.laser;

  ASSERT_EQ(scan.beam_count, 181);
  EXPECT_DOUBLE_EQ(scan.angle_min, -kPi / 2.0);
  EXPECT_DOUBLE_EQ(scan.angle_increment, kPi / 180.0);
  EXPECT_DOUBLE_EQ(scan.max_range, 4.5);
  EXPECT_EQ(scan.stamp, config.period);

  // Beam 90 looks straight ahead (north) at the circle.
  EXPECT_TRUE(scan.valid[90]);
  EXPECT_FLOAT_EQ(scan.range[90], 2.0F);
  // Beams 0 and 180 look west and east: walls at 5 m, beyond the 4.5 m range.
  EXPECT_FALSE(scan.valid[0]);
  EXPECT_EQ(scan.range[0], 0.0F);
  EXPECT_FALSE(scan.valid[180]);
  EXPECT_EQ(scan.range[180], 0.0F);
  // Beam 135 looks north-east (45 degrees right): the walls are 5 * sqrt(2) away, nothing closer.
  EXPECT_FALSE(scan.valid[135]);
  // Beam 40 looks 50 degrees left of north: it meets the square's bottom edge (y = 7) at x = 2.62,
  // after 2 / cos(50 deg) metres.
  EXPECT_TRUE(scan.valid[40]);
  EXPECT_NEAR(scan.range[40], 2.0 / std::cos(hal::deg_to_rad(50.0)), 1e-5);
  // Slots past beam_count are cleared.
  EXPECT_FALSE(scan.valid[181]);
}

TEST(SimRayCast, LaserBeamsTurnWithTheRobot) {
  SimConfig config;
  config.laser_beams = 1;  // a single beam looks straight ahead
  World world = test_world();
  world.start = {5.0, 5.0, kPi / 2.0};  // facing east
  SimRobot robot(world, config);
  hal::SensorFrame frame;
  ASSERT_TRUE(robot.sensors().read(frame));
  EXPECT_EQ(frame.laser.beam_count, 1);
  EXPECT_EQ(frame.laser.angle_min, 0.0);
  EXPECT_EQ(frame.laser.angle_increment, 0.0);
  EXPECT_TRUE(frame.laser.valid[0]);
  EXPECT_FLOAT_EQ(frame.laser.range[0], 5.0F);
}

}  // namespace
}  // namespace ringlet::sim_hal
