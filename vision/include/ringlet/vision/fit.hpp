#pragma once
// Least-squares fits on ground points: a total-least-squares line (principal axis) and an
// algebraic circle (Kåsa). Both are closed form and allocation-free.
#include <optional>
#include <span>

#include "ringlet/hal/geometry.hpp"

namespace ringlet::vision {

/// A line through `point` along the unit vector (dx, dy); normal = (−dy, dx).
struct Line2 {
  hal::RobotPoint point{};
  double dx = 1.0;
  double dy = 0.0;
  [[nodiscard]] double signed_distance(const hal::RobotPoint& p) const noexcept {
    return -dy * (p.x - point.x) + dx * (p.y - point.y);
  }
  [[nodiscard]] double along(const hal::RobotPoint& p) const noexcept { return dx * (p.x - point.x) + dy * (p.y - point.y); }
  [[nodiscard]] hal::RobotPoint at(double t) const noexcept { return {point.x + t * dx, point.y + t * dy}; }
};

struct Circle2 {
  hal::RobotPoint centre{};
  double radius = 0.0;
};

/// Points are read through an index list so the caller's subsets need no copies.
struct IndexedPoints {
  std::span<const hal::RobotPoint> points;
  std::span<const int> index;
  [[nodiscard]] std::size_t size() const noexcept { return index.size(); }
  [[nodiscard]] const hal::RobotPoint& operator[](std::size_t i) const noexcept {
    return points[static_cast<std::size_t>(index[i])];
  }
};

/// The line minimising the sum of squared perpendicular distances; none for < 2 points or all
/// points equal.
[[nodiscard]] std::optional<Line2> fit_line_tls(const IndexedPoints& pts) noexcept;
/// Root mean square perpendicular distance.
[[nodiscard]] double line_rms(const Line2& line, const IndexedPoints& pts) noexcept;

/// Kåsa's algebraic circle fit (least squares on x² + y² + Dx + Ey + F = 0, centred on the mean
/// for conditioning); none for < 3 points or (nearly) collinear points.
[[nodiscard]] std::optional<Circle2> fit_circle(const IndexedPoints& pts) noexcept;
/// Root mean square of |distance to centre − radius|.
[[nodiscard]] double circle_rms(const Circle2& c, const IndexedPoints& pts) noexcept;

}  // namespace ringlet::vision
