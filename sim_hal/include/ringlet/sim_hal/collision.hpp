#pragma once
// Geometric queries against a World. Allocation-free: they run inside the cycle.
#include <limits>

#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal {

/// Distance along a ray from `origin` with heading `bearing` (the geometry.hpp convention: 0 = +y,
/// pi/2 = +x) to the first obstacle or wall, or +infinity if nothing is hit within `max_range`.
[[nodiscard]] double cast_ray(const World& world, Vec2 origin, double bearing, double max_range) noexcept;

/// True when a disc of `radius` at `centre` overlaps an obstacle or leaves the bounds.
[[nodiscard]] bool disc_collides(const World& world, Vec2 centre, double radius) noexcept;

}  // namespace ringlet::sim_hal
