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

/// A point in the robot frame: x straight ahead, y to the robot's left (the NAO's convention, so
/// that a head yaw of atan2(y, x), positive to the left, looks at it).
struct RobotPoint {
  double x = 0.0;
  double y = 0.0;
};

/// A point in the world frame (m).
struct WorldPoint {
  double x = 0.0;
  double y = 0.0;
};

/// The world point (wx, wy) seen from `pose`: ahead is (sin theta, cos theta), left is
/// (-cos theta, sin theta) in the world frame.
inline RobotPoint to_robot_frame(const Pose2& pose, double wx, double wy) noexcept {
  const double dx = wx - pose.x;
  const double dy = wy - pose.y;
  const double s = std::sin(pose.theta);
  const double c = std::cos(pose.theta);
  return {dx * s + dy * c, -dx * c + dy * s};
}

/// The inverse of to_robot_frame, made once per pose for many points (sin and cos computed once):
/// a robot-frame point (x ahead, y left) is pose + x·ahead + y·left in the world. Every user goes
/// through this one expression order, so they all get the same bits.
class RobotToWorld {
 public:
  explicit RobotToWorld(const Pose2& pose) noexcept
      : x_(pose.x), y_(pose.y), s_(std::sin(pose.theta)), c_(std::cos(pose.theta)) {}

  [[nodiscard]] WorldPoint point(double ahead, double left) const noexcept {
    return {x_ + ahead * s_ - left * c_, y_ + ahead * c_ + left * s_};
  }
  [[nodiscard]] WorldPoint operator()(const RobotPoint& p) const noexcept { return point(p.x, p.y); }
  /// A robot-frame direction in the world (rotation only).
  [[nodiscard]] WorldPoint direction(double ahead, double left) const noexcept {
    return {ahead * s_ - left * c_, ahead * c_ + left * s_};
  }

 private:
  double x_, y_, s_, c_;
};

constexpr double deg_to_rad(double d) noexcept { return d * std::numbers::pi / 180.0; }
constexpr double rad_to_deg(double r) noexcept { return r * 180.0 / std::numbers::pi; }

}  // namespace ringlet::hal
