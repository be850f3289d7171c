// The shipped SPL field world on its own: its markings match the rule book's dimensions, and it
// has the posts, robots, ball and sunlight the vision scenario needs. Its mission (the goal loop,
// its clearance from the obstacles, and a waypoint follower driving it with the laser clear of the
// Safety machine's stop range) is the firmware configuration's: see
// tests/firmware/mission_path_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal {
namespace {

World spl_field() { return load_world(RINGLET_SIM_WORLDS_DIR "/spl_field.world"); }

bool has_marking(const World& w, Vec2 a, Vec2 b) {
  const auto same = [](Vec2 p, Vec2 q) { return std::fabs(p.x - q.x) < 1e-9 && std::fabs(p.y - q.y) < 1e-9; };
  return std::any_of(w.markings.begin(), w.markings.end(), [&](const Marking& m) {
    return m.width == 0.05 && ((same(m.a, a) && same(m.b, b)) || (same(m.a, b) && same(m.b, a)));
  });
}

TEST(SimSplField, RuleBookDimensions) {
  const World w = spl_field();
  EXPECT_EQ(w.name, "SPL field");
  EXPECT_DOUBLE_EQ(w.max.x - w.min.x, 10.4);
  EXPECT_DOUBLE_EQ(w.max.y - w.min.y, 7.4);
  EXPECT_TRUE(has_marking(w, {-4.5, -3.0}, {4.5, -3.0}));  // touch lines: 9 m
  EXPECT_TRUE(has_marking(w, {-4.5, 3.0}, {4.5, 3.0}));
  EXPECT_TRUE(has_marking(w, {-4.5, -3.0}, {-4.5, 3.0}));  // goal lines: 6 m
  EXPECT_TRUE(has_marking(w, {4.5, -3.0}, {4.5, 3.0}));
  EXPECT_TRUE(has_marking(w, {0.0, -3.0}, {0.0, 3.0}));    // centre line
  EXPECT_TRUE(has_marking(w, {-2.85, -2.0}, {-2.85, 2.0}));  // penalty area: 1.65 deep, 4 wide
  EXPECT_TRUE(has_marking(w, {2.85, -2.0}, {2.85, 2.0}));
  EXPECT_TRUE(has_marking(w, {-3.9, -1.1}, {-3.9, 1.1}));  // goal area: 0.6 deep, 2.2 wide
  EXPECT_TRUE(has_marking(w, {3.9, -1.1}, {3.9, 1.1}));
  EXPECT_TRUE(has_marking(w, {-3.25, 0.0}, {-3.15, 0.0}));  // penalty marks 1.3 m out
  EXPECT_TRUE(has_marking(w, {3.2, -0.05}, {3.2, 0.05}));
  ASSERT_EQ(w.rings.size(), 1U);
  EXPECT_EQ(w.rings[0].radius, 0.75);
  const auto posts = std::count_if(w.circles.begin(), w.circles.end(),
                                   [](const Circle& c) { return c.kind == ObstacleKind::kPost; });
  const auto robots = std::count_if(w.circles.begin(), w.circles.end(),
                                    [](const Circle& c) { return c.kind == ObstacleKind::kRobot; });
  EXPECT_EQ(posts, 4);
  EXPECT_GE(robots, 3);
  EXPECT_TRUE(w.polygons.empty());  // every obstacle is round: posts and robots
  EXPECT_TRUE(w.ball.has_value());
  EXPECT_GT(w.lighting.sun_strength, 0.0);
}

}  // namespace
}  // namespace ringlet::sim_hal
