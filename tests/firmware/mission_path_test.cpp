// The shipped missions in their worlds: each configuration's goals ([mission] goals) laid over the
// world its [sim] section names. Goals live in the configuration, obstacles in the world file, so
// only here can one check that they fit together: every goal inside the world, every obstacle at
// least 1.2 m from the straight lines start -> goal 1 -> goal 2 -> ..., and the Mission machine's
// plain waypoint follower (behaviour::move_to_waypoint with the configuration's [follower], no
// obstacle avoidance, no Safety machine) drives the whole loop on the simulated robot without
// touching anything and without the laser seeing anything inside the Safety machine's stop range.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "ringlet/behaviour/move_to_waypoint.hpp"
#include "ringlet/firmware/config.hpp"
#include "ringlet/sim_hal/sim_robot.hpp"
#include "ringlet/sim_hal/world.hpp"

namespace ringlet::firmware {
namespace {

using sim_hal::Vec2;

const std::filesystem::path kConfigDir = std::filesystem::path(RINGLET_SHIPPED_CONFIG).parent_path();
constexpr double kRequiredClearance = 1.2;  // m between an obstacle and a goal-to-goal line

struct ShippedMission {
  const char* name;
  const char* config;  // in firmware/config/
  std::size_t min_goals;
  std::size_t max_goals;
};

// Test names and failure messages show the mission's name.
void PrintTo(const ShippedMission& mission, std::ostream* out) { *out << mission.name; }

const ShippedMission kShippedMissions[] = {
    {"Courtyard", "courtyard.toml", 6, 8},  // a loop round the yard
    {"SplField", "spl_field.toml", 4, 8},   // a loop round the field
};

/// The world file the configuration's [sim] world names, resolved against the configuration's
/// folder as the firmware does. (FirmwareConfig keeps the backend's section opaque.)
std::filesystem::path world_path(const std::filesystem::path& config_path) {
  const toml::table table = toml::parse_file(config_path.string());
  const std::optional<std::string> world = table["sim"]["world"].value<std::string>();
  if (!world) throw std::runtime_error(config_path.string() + ": no [sim] world");
  return config_path.parent_path() / *world;
}

struct Mission {
  FirmwareConfig config;
  sim_hal::World world;
};

Mission load_mission(const ShippedMission& shipped) {
  const std::filesystem::path path = kConfigDir / shipped.config;
  Mission mission{load_config(path), sim_hal::load_world(world_path(path))};
  return mission;
}

Vec2 as_vec(const behaviour::Waypoint& goal) { return {goal.x, goal.y}; }

double cross(Vec2 o, Vec2 a, Vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  const double t = length2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

double segment_segment_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const bool crossing = (cross(a, b, c) > 0.0) != (cross(a, b, d) > 0.0) &&
                        (cross(c, d, a) > 0.0) != (cross(c, d, b) > 0.0);
  if (crossing) return 0.0;
  return std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d), point_segment_distance(c, a, b),
                   point_segment_distance(d, a, b)});
}

/// Clearance from the nearest obstacle to the line segment [a, b]; 0 when the line runs into one.
double clearance(const sim_hal::World& world, Vec2 a, Vec2 b) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const sim_hal::Circle& c : world.circles) {
    nearest = std::min(nearest, point_segment_distance(c.centre, a, b) - c.radius);
  }
  for (const sim_hal::Polygon& polygon : world.polygons) {
    const auto& v = polygon.vertices;
    for (std::size_t i = 0; i < v.size(); ++i) {
      nearest = std::min(nearest, segment_segment_distance(a, b, v[i], v[(i + 1) % v.size()]));
    }
  }
  return nearest;
}

class ShippedMissionTest : public testing::TestWithParam<ShippedMission> {};

TEST_P(ShippedMissionTest, GoalsAreALoopInsideTheWorld) {
  const Mission m = load_mission(GetParam());
  const std::vector<behaviour::Waypoint>& goals = m.config.mission.goals;
  EXPECT_GE(goals.size(), GetParam().min_goals);
  EXPECT_LE(goals.size(), GetParam().max_goals);
  // The report names the world the run was made of: the same file this test loaded.
  ASSERT_NE(m.config.backend_settings, nullptr);
  EXPECT_EQ(m.config.backend_settings->source_name(), world_path(kConfigDir / GetParam().config).filename().string());
  for (std::size_t i = 0; i < goals.size(); ++i) {
    SCOPED_TRACE(testing::Message() << "goal " << i + 1 << " (" << goals[i].x << ", " << goals[i].y << ")");
    EXPECT_GE(goals[i].x, m.world.min.x);
    EXPECT_LE(goals[i].x, m.world.max.x);
    EXPECT_GE(goals[i].y, m.world.min.y);
    EXPECT_LE(goals[i].y, m.world.max.y);
    // No goal is where the robot already stands or where the previous goal was: every leg is a move.
    const Vec2 from = i == 0 ? Vec2{m.world.start.x, m.world.start.y} : as_vec(goals[i - 1]);
    EXPECT_GT(std::hypot(goals[i].x - from.x, goals[i].y - from.y), 2.0 * m.config.mission.goal_tolerance);
  }
}

TEST_P(ShippedMissionTest, ObstaclesKeepClearOfTheGoalLines) {
  const Mission m = load_mission(GetParam());
  ASSERT_FALSE(m.config.mission.goals.empty());
  Vec2 from{m.world.start.x, m.world.start.y};
  for (std::size_t i = 0; i < m.config.mission.goals.size(); ++i) {
    const Vec2 to = as_vec(m.config.mission.goals[i]);
    SCOPED_TRACE(testing::Message() << "line to goal " << i + 1 << " (" << to.x << ", " << to.y << ")");
    EXPECT_GE(clearance(m.world, from, to), kRequiredClearance);
    from = to;
  }
}

TEST_P(ShippedMissionTest, WaypointFollowerDrivesTheLoopWithoutCollisions) {
  const Mission m = load_mission(GetParam());
  const std::vector<behaviour::Waypoint>& goals = m.config.mission.goals;
  ASSERT_FALSE(goals.empty());
  const double tolerance = m.config.mission.goal_tolerance;

  // The loop's length as straight lines, less what the tolerance lets each leg cut short: no way
  // round the loop is shorter.
  double shortest = 0.0;
  Vec2 from{m.world.start.x, m.world.start.y};
  for (const behaviour::Waypoint& goal : goals) {
    shortest += std::hypot(goal.x - from.x, goal.y - from.y) - 2.0 * tolerance;
    from = as_vec(goal);
  }

  sim_hal::SimRobot robot(m.world, sim_hal::SimConfig{});
  const auto max_steps = static_cast<std::uint64_t>(m.config.mission.timeout_s / hal::to_seconds(robot.config().period));
  std::size_t next = 0;
  double nearest = std::numeric_limits<double>::infinity();
  hal::SensorFrame frame;
  while (next < goals.size() && robot.steps() < max_steps) {
    robot.sensors().read(frame);
    for (std::size_t i = 0; i < frame.laser.beam_count; ++i) {
      if (frame.laser.valid[i]) nearest = std::min(nearest, static_cast<double>(frame.laser.range[i]));
    }
    const hal::Pose2& pose = frame.pose.pose;
    if (std::hypot(goals[next].x - pose.x, goals[next].y - pose.y) < tolerance) {
      ++next;
      continue;
    }
    hal::ActuatorCommand cmd;
    cmd.drive = behaviour::move_to_waypoint(pose, goals[next], m.config.follower);
    robot.actuators().write(cmd);
  }
  EXPECT_EQ(next, goals.size()) << "stuck before goal " << next + 1 << " after " << hal::to_seconds(robot.sim_time())
                                << " s";
  EXPECT_EQ(robot.collisions(), 0U);
  EXPECT_LE(hal::to_seconds(robot.sim_time()), m.config.mission.timeout_s);
  EXPECT_GE(robot.distance_travelled(), shortest);  // it really went round
  EXPECT_GT(nearest, m.config.safety.stop_range);   // the Safety machine never had to stop it
}

INSTANTIATE_TEST_SUITE_P(Shipped, ShippedMissionTest, testing::ValuesIn(kShippedMissions),
                         [](const testing::TestParamInfo<ShippedMission>& param) {
                           return std::string(param.param.name);
                         });

}  // namespace
}  // namespace ringlet::firmware
