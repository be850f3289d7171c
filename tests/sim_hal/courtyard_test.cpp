// The shipped courtyard world: it parses, its obstacles keep clear of the straight goal-to-goal
// lines, and a plain waypoint follower (the controller the firmware starts with: steer at the
// goal, no obstacle avoidance) drives the whole loop without touching anything.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "ringlet/sim_hal/sim_robot.hpp"

namespace ringlet::sim_hal {
namespace {

const std::string kCourtyard = std::string(RINGLET_SIM_WORLDS_DIR) + "/courtyard.world";
constexpr double kRequiredClearance = 1.2;  // metres between an obstacle and a goal-to-goal line
constexpr double kGoalTolerance = 0.3;

double cross(Vec2 o, Vec2 a, Vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

double segment_segment_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const bool crossing = (cross(a, b, c) > 0.0) != (cross(a, b, d) > 0.0) &&
                        (cross(c, d, a) > 0.0) != (cross(c, d, b) > 0.0);
  if (crossing) return 0.0;
  return std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d), point_segment_distance(c, a, b),
                   point_segment_distance(d, a, b)});
}

/// Clearance from an obstacle to the line segment [a, b]; 0 when the line runs into it.
double clearance(const World& world, Vec2 a, Vec2 b) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const Circle& c : world.circles) {
    nearest = std::min(nearest, point_segment_distance(c.centre, a, b) - c.radius);
  }
  for (const Polygon& polygon : world.polygons) {
    const auto& v = polygon.vertices;
    for (std::size_t i = 0; i < v.size(); ++i) {
      nearest = std::min(nearest, segment_segment_distance(a, b, v[i], v[(i + 1) % v.size()]));
    }
  }
  return nearest;
}

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
  EXPECT_GE(world.goals.size(), 6U);
  EXPECT_LE(world.goals.size(), 8U);
}

TEST(SimCourtyard, ObstaclesKeepClearOfTheGoalLines) {
  const World world = load_world(kCourtyard);
  Vec2 from{world.start.x, world.start.y};
  for (std::size_t i = 0; i < world.goals.size(); ++i) {
    SCOPED_TRACE(testing::Message() << "line to goal " << i + 1);
    EXPECT_GE(clearance(world, from, world.goals[i]), kRequiredClearance);
    from = world.goals[i];
  }
}

/// The simplest waypoint follower: steer in proportion to the heading error, slow down while
/// pointing away from the goal.
hal::ActuatorCommand follow(const hal::Pose2& pose, Vec2 goal) {
  const double error = hal::wrap_angle(hal::bearing_to(pose, goal.x, goal.y) - pose.theta);
  hal::ActuatorCommand cmd;
  cmd.drive.curvature = std::clamp(2.0 * error, -2.0, 2.0);
  cmd.drive.velocity = std::max(0.2, 1.0 - std::fabs(error) / (std::numbers::pi / 2.0));
  return cmd;
}

TEST(SimCourtyard, WaypointFollowerDrivesTheLoopWithoutCollisions) {
  SimRobot robot(load_world(kCourtyard), SimConfig{});
  const std::vector<Vec2>& goals = robot.world().goals;
  const auto max_steps = static_cast<std::uint64_t>(300.0 / hal::to_seconds(robot.config().period));
  std::size_t next = 0;
  hal::SensorFrame frame;
  while (next < goals.size() && robot.steps() < max_steps) {
    robot.sensors().read(frame);
    const hal::Pose2& pose = frame.pose.pose;
    if (std::hypot(goals[next].x - pose.x, goals[next].y - pose.y) < kGoalTolerance) {
      ++next;
      continue;
    }
    robot.actuators().write(follow(pose, goals[next]));
  }
  EXPECT_EQ(next, goals.size()) << "stuck before goal " << next + 1 << " after "
                                << hal::to_seconds(robot.sim_time()) << " s";
  EXPECT_EQ(robot.collisions(), 0U);
  EXPECT_LE(hal::to_seconds(robot.sim_time()), 300.0);
  EXPECT_GT(robot.distance_travelled(), 40.0);  // it really went round the yard
}

}  // namespace
}  // namespace ringlet::sim
