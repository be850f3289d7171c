#pragma once
// The reactive layer's action space (Powers & Balch §III-A): an array of constant-curvature arcs
// over ±κmax, and how far the robot can drive along each before it enters the configuration space
// (a disc of some radius) around an obstacle point. All arrays are fixed-size: nothing allocates.
//
// Frames: obstacle points are in the robot frame (x ahead, y to the left, hal::RobotPoint). A
// positive curvature turns clockwise seen from above, i.e. to the right (hal/geometry.hpp), so
// the centre of an arc of curvature κ > 0 lies at (0, −1/κ).
#include <array>
#include <cstddef>
#include <string>

#include "ringlet/hal/geometry.hpp"
#include "ringlet/hal/sensors.hpp"

namespace ringlet::behaviour::reactive {

inline constexpr int kMaxArcs = 63;

/// `count` arcs evenly spaced over [−κmax, κmax]; an odd count includes the straight one.
struct ArcSet {
  int count = 25;
  double max_curvature = 2.0;  // 1/m

  [[nodiscard]] double curvature(int i) const noexcept {
    return count == 1 ? 0.0 : max_curvature * (2.0 * i / (count - 1) - 1.0);
  }
  /// Empty when usable, else what is wrong (names the field).
  [[nodiscard]] std::string validate() const;
};

/// Per-arc numbers (votes, speeds, distances); only the first ArcSet::count are used.
using PerArc = std::array<double, kMaxArcs>;

/// Obstacle points in the robot frame: the valid beams of a laser scan.
struct ObstaclePoints {
  std::array<hal::RobotPoint, hal::LaserScan::kMaxBeams> point{};
  std::size_t count = 0;
};

/// The end points of the valid beams (an invalid beam saw nothing within range: no point).
[[nodiscard]] ObstaclePoints obstacles_from_scan(const hal::LaserScan& scan) noexcept;

/// The distance along the arc of curvature `kappa` from the robot to where it first comes within
/// `radius` of `p`, `limit` if not within `limit`. If the robot is already that close: 0 when the
/// arc brings it closer still, `limit` when it leads away (the way out).
[[nodiscard]] double distance_to_contact(double kappa, const hal::RobotPoint& p, double radius, double limit) noexcept;

/// For every arc, the distance to the first contact with the configuration space of radius
/// `radius` around any of the points, capped at `limit`.
void clearances(const ArcSet& arcs, const ObstaclePoints& obstacles, double radius, double limit, PerArc& out) noexcept;

}  // namespace ringlet::behaviour::reactive
