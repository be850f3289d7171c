#pragma once
// A picture of a world and what happened in it: bounds, obstacles, markings, ball, the mission's
// numbered goals (filled when reached), the start pose, the driven trajectory and collision points.
#include <cstddef>
#include <filesystem>
#include <ostream>
#include <span>

#include "ringlet/hal/ground_truth.hpp"
#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal {

void write_world_svg(std::ostream& out, const World& world, const hal::RunPicture& overlay);
/// Writes to a file; throws std::runtime_error naming the path if it cannot be written.
void write_world_svg(const std::filesystem::path& path, const World& world, const hal::RunPicture& overlay);

}  // namespace ringlet::sim_hal
