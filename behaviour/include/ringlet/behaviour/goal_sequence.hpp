#pragma once
// An ordered goal sequence: a goal counts as reached when the robot comes within the tolerance of
// it, then the next one is the target. Plain functions over the goals' coordinates, so that the
// Mission machine keeps its progress in its own variables and the goals stay whiteboard data.
#include <cstddef>
#include <span>

#include "ringlet/hal/geometry.hpp"

namespace ringlet::behaviour {

/// Goals reached once the robot is at `pose`: from `reached` on, every next goal within
/// `tolerance` (m) of the pose counts too. `x` and `y` hold the goals in order (same length).
/// No allocation: runs in the cycle.
[[nodiscard]] std::size_t goals_reached_at(std::span<const double> x, std::span<const double> y,
                                           std::size_t reached, const hal::Pose2& pose, double tolerance) noexcept;

}  // namespace ringlet::behaviour
