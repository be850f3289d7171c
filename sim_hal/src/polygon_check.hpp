#pragma once
// Is a vertex list a simple polygon? The collision code relies on it: the inside test and the
// edge distances only describe the obstacle the author meant when the outline does not cross itself.
#include <cstddef>
#include <optional>
#include <span>

#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal::detail {

struct PolygonDefect {
  enum class Kind { kRepeatedVertex, kEdgesIntersect };
  Kind kind = Kind::kEdgesIntersect;
  std::size_t first = 0;   // 0-based: vertex indices for kRepeatedVertex, edge indices otherwise
  std::size_t second = 0;  // (edge i runs from vertex i to vertex i+1, the last one back to 0)
};

/// The first defect found, or nothing for a simple polygon. Needs at least 3 vertices.
[[nodiscard]] std::optional<PolygonDefect> find_polygon_defect(std::span<const Vec2> vertices) noexcept;

}  // namespace ringlet::sim_hal::detail
