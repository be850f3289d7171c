#pragma once
// Seeded random goals in a world (Powers & Balch §IV-A: "a series of randomly generated goals"):
// uniform over the world's bounds, kept where a disc of `clearance` touches nothing, each at least
// `min_leg` from the one before. The same seed gives the same goals on every host (splitmix64,
// arithmetic on integers and exactly representable doubles).
#include <cstdint>
#include <filesystem>
#include <vector>

#include "mission.hpp"
#include "ringlet/behaviour/move_to_waypoint.hpp"
#include "ringlet/sim_hal/world.hpp"

namespace ringlet::experiments {

struct GoalRules {
  double clearance = 1.0;  // m: free radius around a goal
  double min_leg = 6.0;    // m: least straight distance from the previous goal (or the start)
};

/// `count` goals, the first measured from the world's start.
[[nodiscard]] std::vector<behaviour::Waypoint> random_goals(const sim_hal::World& world, std::size_t count,
                                                            std::uint64_t seed, const GoalRules& rules = {});

/// The straight-line length of the legs from `from` through every goal.
[[nodiscard]] double straight_line_length(behaviour::Waypoint from, const std::vector<behaviour::Waypoint>& goals);

/// Leg i of a goal sequence as a mission of its own: goal i, from goal i − 1 (the world's start
/// for i = 0) heading as the robot arrived there (from goal i − 2, or the world's start), with
/// the time limit leg_timeout() of its straight length. A goal a system misses costs only itself.
/// Its files go to `work_dir` under `tag`.
[[nodiscard]] MissionSpec leg_mission(const std::filesystem::path& config, const sim_hal::World& world,
                                      const std::vector<behaviour::Waypoint>& goals, std::size_t i,
                                      const std::filesystem::path& work_dir, const std::string& tag);

/// 30 s plus 4 s per straight-line metre: a quarter of the top speed (1 m/s) on average.
[[nodiscard]] double leg_timeout(double straight_m) noexcept;

/// The world a shipped configuration's [sim] world names (relative to the configuration).
[[nodiscard]] sim_hal::World world_of(const std::filesystem::path& config);

}  // namespace ringlet::experiments
