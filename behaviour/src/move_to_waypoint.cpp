#include "ringlet/behaviour/move_to_waypoint.hpp"

#include <algorithm>
#include <cmath>

#include "ringlet/hal/portable_math.hpp"

namespace ringlet::behaviour {

double heading_error(const hal::Pose2& pose, const Waypoint& target) noexcept {
  return hal::wrap_angle(hal::bearing_to(pose, target.x, target.y) - pose.theta);
}

hal::DriveCommand move_to_waypoint(const hal::Pose2& pose, const Waypoint& target,
                                   const MoveToWaypointParams& p) noexcept {
  const double error = heading_error(pose, target);
  // theta' = v kappa: a positive error (target clockwise) needs theta to grow, so kappa > 0.
  const double curvature = std::clamp(p.gain * error, -p.max_curvature, p.max_curvature);

  const double turn = std::min(std::abs(error) / p.full_turn_error, 1.0);
  double speed = p.max_speed - (p.max_speed - p.min_speed) * turn;
  if (p.approach_radius > 0.0) {
    const double distance = hal::portable_hypot(target.x - pose.x, target.y - pose.y);
    speed = std::min(speed, std::max(p.min_speed, p.max_speed * distance / p.approach_radius));
  }
  return {curvature, speed};
}

}  // namespace ringlet::behaviour
