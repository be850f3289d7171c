// The shipped SPL field: its markings match the rule book's dimensions, and the plain waypoint
// follower (the Mission machine's controller) drives its goal loop without touching anything and
// without the laser ever seeing something closer than the Safety machine's 0.9 m.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "ringlet/sim_hal/sim_robot.hpp"

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
  EXPECT_TRUE(w.ball.has_value());
  EXPECT_GT(w.lighting.sun_strength, 0.0);
}

double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

TEST(SimSplField, ObstaclesKeepClearOfTheGoalLines) {
  const World w = spl_field();
  EXPECT_TRUE(w.polygons.empty());
  Vec2 from{w.start.x, w.start.y};
  for (std::size_t i = 0; i < w.goals.size(); ++i) {
    for (const Circle& c : w.circles) {
      EXPECT_GE(point_segment_distance(c.centre, from, w.goals[i]) - c.radius, 1.2)
          << "goal " << i + 1 << ", obstacle at " << c.centre.x << ", " << c.centre.y;
    }
    from = w.goals[i];
  }
}

TEST(SimSplField, WaypointFollowerDrivesTheLoopAndTheLaserStaysClear) {
  SimRobot robot(spl_field(), SimConfig{});
  const std::vector<Vec2>& goals = robot.world().goals;
  std::size_t next = 0;
  double nearest = std::numeric_limits<double>::infinity();
  hal::SensorFrame frame;
  while (next < goals.size() && robot.steps() < 20'000) {
    robot.sensors().read(frame);
    for (std::size_t i = 0; i < frame.laser.beam_count; ++i) {
      if (frame.laser.valid[i]) nearest = std::min(nearest, static_cast<double>(frame.laser.range[i]));
    }
    const hal::Pose2& pose = frame.pose.pose;
    if (std::hypot(goals[next].x - pose.x, goals[next].y - pose.y) < 0.3) {
      ++next;
      continue;
    }
    const double error = hal::wrap_angle(hal::bearing_to(pose, goals[next].x, goals[next].y) - pose.theta);
    hal::ActuatorCommand cmd;
    cmd.drive.curvature = std::clamp(2.0 * error, -2.0, 2.0);
    cmd.drive.velocity = std::max(0.2, 1.0 - std::fabs(error) / (std::numbers::pi / 2.0));
    robot.actuators().write(cmd);
  }
  EXPECT_EQ(next, goals.size());
  EXPECT_EQ(robot.collisions(), 0U);
  EXPECT_GT(nearest, 0.9);  // the Safety machine's stop distance
}

}  // namespace
}  // namespace ringlet::sim
