// The shipped courtyard world on its own: it parses, with the size and the kinds of things the
// courtyard scenario is built from. Its mission (the goals, their clearance from the obstacles,
// and a waypoint follower driving the loop) is the firmware configuration's: see
// tests/firmware/mission_path_test.cpp.
#include <gtest/gtest.h>

#include <string>

#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal {
namespace {

const std::string kCourtyard = std::string(RINGLET_SIM_WORLDS_DIR) + "/courtyard.world";

TEST(SimCourtyard, Parses) {
  const World world = load_world(kCourtyard);
  EXPECT_EQ(world.name, "Courtyard");
  EXPECT_EQ(world.min.x, 0.0);
  EXPECT_EQ(world.min.y, 0.0);
  EXPECT_EQ(world.max.x, 20.0);
  EXPECT_EQ(world.max.y, 14.0);
  EXPECT_NEAR(world.start.x, 1.5, 0.5);
  EXPECT_NEAR(world.start.y, 1.5, 0.5);
  EXPECT_EQ(world.start.theta, 0.0);
  const std::size_t obstacles = world.circles.size() + world.polygons.size();
  EXPECT_GE(obstacles, 5U);
  EXPECT_LE(obstacles, 8U);
  EXPECT_GE(world.polygons.size(), 2U);
  EXPECT_FALSE(world.markings.empty());
  EXPECT_TRUE(world.ball.has_value());
}

}  // namespace
}  // namespace ringlet::sim_hal
