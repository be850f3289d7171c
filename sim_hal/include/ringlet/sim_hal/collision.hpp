#pragma once
#include <cstdint>
#include <vector>
// Geometric queries against a World. Allocation-free: they run inside the cycle.
#include <limits>

#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal {

/// Distance along a ray from `origin` with heading `bearing` (the geometry.hpp convention: 0 = +y,
/// pi/2 = +x) to the first obstacle or wall, or +infinity if nothing is hit within `max_range`.
[[nodiscard]] double cast_ray(const World& world, Vec2 origin, double bearing, double max_range) noexcept;

/// The obstacles one scan's rays could meet: those within max_range of the origin. Sized for the
/// world at start-up (reserve); select() never allocates. A ray cast against them gives exactly
/// what cast_ray gives against the whole world (the others lie out of range), but a wood of
/// 400 trees costs a laser of 181 beams a tenth of the work.
class RayCandidates {
 public:
  void reserve(const World& world);
  void select(const World& world, Vec2 origin, double max_range) noexcept;
  [[nodiscard]] double cast(const World& world, Vec2 origin, double bearing, double max_range) const noexcept;

 private:
  std::vector<std::uint32_t> circles_, polygons_;
};

/// True when a disc of `radius` at `centre` overlaps an obstacle or leaves the bounds.
[[nodiscard]] bool disc_collides(const World& world, Vec2 centre, double radius) noexcept;

}  // namespace ringlet::sim_hal
