#include "polygon_check.hpp"

#include "vec2_math.hpp"

namespace ringlet::sim_hal::detail {
namespace {

int orientation(Vec2 a, Vec2 b, Vec2 c) noexcept {
  const double turn = cross(b - a, c - a);
  return (turn > 0.0) - (turn < 0.0);
}

/// p is known to be collinear with [a, b]: is it within the segment?
bool within_box(Vec2 a, Vec2 b, Vec2 p) noexcept {
  const bool in_x = (a.x <= p.x && p.x <= b.x) || (b.x <= p.x && p.x <= a.x);
  const bool in_y = (a.y <= p.y && p.y <= b.y) || (b.y <= p.y && p.y <= a.y);
  return in_x && in_y;
}

/// Closed segments [a, b] and [c, d] share at least one point.
bool segments_touch(Vec2 a, Vec2 b, Vec2 c, Vec2 d) noexcept {
  const int o1 = orientation(a, b, c);
  const int o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a);
  const int o4 = orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && within_box(a, b, c)) || (o2 == 0 && within_box(a, b, d)) ||
         (o3 == 0 && within_box(c, d, a)) || (o4 == 0 && within_box(c, d, b));
}

}  // namespace

std::optional<PolygonDefect> find_polygon_defect(std::span<const Vec2> vertices) noexcept {
  const std::size_t n = vertices.size();
  const auto vertex = [&](std::size_t i) { return vertices[i % n]; };

  // A repeated consecutive vertex makes a zero-length edge: report it as such, it is clearer
  // than the intersection it would otherwise show up as.
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = vertex(i);
    const Vec2 b = vertex(i + 1);
    if (a.x == b.x && a.y == b.y) return PolygonDefect{PolygonDefect::Kind::kRepeatedVertex, i, (i + 1) % n};
  }

  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = vertex(i);
    const Vec2 b = vertex(i + 1);
    // Consecutive edges meet at their shared vertex by construction; they overlap beyond it only
    // when the outline folds straight back on itself.
    const Vec2 c = vertex(i + 2);
    if (cross(b - a, c - b) == 0.0 && dot(b - a, c - b) < 0.0) {
      return PolygonDefect{PolygonDefect::Kind::kEdgesIntersect, i, (i + 1) % n};
    }
    // Every other pair must not touch at all. Edge n-1 is adjacent to edge 0, hence the bound.
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (segments_touch(a, b, vertex(j), vertex(j + 1))) {
        return PolygonDefect{PolygonDefect::Kind::kEdgesIntersect, i, j};
      }
    }
  }
  return std::nullopt;
}

}  // namespace ringlet::sim_hal::detail
