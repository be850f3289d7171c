#pragma once
// A picture of a world and what happened in it: bounds, obstacles, markings, ball, numbered goals
// (filled when reached), the start pose, the driven trajectory and collision points.
#include <cstddef>
#include <filesystem>
#include <ostream>
#include <span>

#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal {

struct RunOverlay {
  std::span<const hal::Pose2> trajectory;  // in driving order
  std::span<const Vec2> collisions;
  std::size_t goals_reached = 0;  // the first N goals are drawn as reached
  std::string_view caption;       // one line under the picture, e.g. the mission summary
};

void write_world_svg(std::ostream& out, const World& world, const RunOverlay& overlay);
/// Writes to a file; throws std::runtime_error naming the path if it cannot be written.
void write_world_svg(const std::filesystem::path& path, const World& world, const RunOverlay& overlay);

}  // namespace ringlet::sim
