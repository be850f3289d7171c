#pragma once
// Least-squares fits on ground points: a total-least-squares line (principal axis) and an
// algebraic circle (Kåsa). Both are closed form and allocation-free.
#include <cmath>
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

/// The geometric circle fit: minimises Σ (|p − centre| − radius)² by Gauss–Newton from `start`
/// (at most `iterations` steps). With `fixed_radius` only the centre moves and the radius stays
/// start.radius — the centre circle's known size, which short arcs cannot measure (Kåsa's fit
/// shrinks their radius under noise). None for < 3 points (< 2 with a fixed radius) or a singular
/// step.
[[nodiscard]] std::optional<Circle2> fit_circle_geometric(const IndexedPoints& pts, const Circle2& start,
                                                          bool fixed_radius, int iterations = 10) noexcept;

/// How a set of points bends away from `line`: the least-squares parabola
/// d(t) = a + b·t + c·t² of their signed distance d against their position t along it (t centred).
/// A circular arc of radius R seen from its chord has |c| ≈ 1 / (2R), its sign says which side
/// its centre is on (c > 0: the normal's side); a straight line has c ≈ 0.
struct Bend {
  double c = 0.0;        // curvature term, 1/m
  double sigma_c = 0.0;  // its standard error, from the residual noise (never below noise_floor_m)
  double t_mid = 0.0;    // the centre of the t range (the parabola's t origin), along the line
  double a = 0.0;        // d at t_mid
  double b = 0.0;        // slope of d at t_mid
  double span = 0.0;     // t range covered
  int n = 0;
  /// How many standard errors c is away from 0.
  [[nodiscard]] double z() const noexcept { return sigma_c > 0.0 ? std::abs(c) / sigma_c : 0.0; }
};
/// None for < 5 points or all at one place along the line.
[[nodiscard]] std::optional<Bend> fit_bend(const Line2& line, const IndexedPoints& pts,
                                           double noise_floor_m = 0.005) noexcept;

}  // namespace ringlet::vision
