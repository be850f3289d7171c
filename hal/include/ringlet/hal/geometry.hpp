#pragma once
// Planar pose convention of Powers & Balch eqs. (16)-(19), used everywhere in Ringlet:
//   x, y in metres in the world frame; theta is the heading measured from the +y axis towards
//   the +x axis (a compass bearing), so that  x' = v sin(theta), y' = v cos(theta),
//   theta' = v kappa. Positive curvature turns the robot clockwise seen from above (+z).
#include <cmath>
#include <numbers>

namespace ringlet::hal {

struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;  // radians, wrapped to (-pi, pi]
};

/// Wraps an angle to (-pi, pi].
inline double wrap_angle(double a) noexcept {
  a = std::remainder(a, 2.0 * std::numbers::pi);
  return a <= -std::numbers::pi ? a + 2.0 * std::numbers::pi : a;
}

/// Bearing (in the convention above) from `from` to the point (x, y).
inline double bearing_to(const Pose2& from, double x, double y) noexcept {
  return std::atan2(x - from.x, y - from.y);
}

constexpr double deg_to_rad(double d) noexcept { return d * std::numbers::pi / 180.0; }
constexpr double rad_to_deg(double r) noexcept { return r * 180.0 / std::numbers::pi; }

}  // namespace ringlet::hal
