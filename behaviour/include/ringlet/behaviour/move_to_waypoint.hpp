#pragma once
// "Move to Waypoint" (Powers & Balch §III-A): a linear control law from the heading error towards
// the waypoint to a commanded curvature. Here it drives the robot alone; with the reactive layer
// it becomes one voting behaviour among five, and this law supplies its preferred arc.
#include "ringlet/hal/actuators.hpp"
#include "ringlet/hal/geometry.hpp"

namespace ringlet::behaviour {

struct Waypoint {
  double x = 0.0;
  double y = 0.0;
};

struct MoveToWaypointParams {
  double gain = 2.0;                // kappa per radian of heading error
  double max_curvature = 2.0;       // 1/m, the robot's steering limit
  double max_speed = 1.0;           // m/s on a straight line
  double min_speed = 0.2;           // m/s: a car-like robot must keep rolling to turn
  double full_turn_error = hal::deg_to_rad(70.0);  // rad: at this heading error the speed has fallen to min_speed
  double approach_radius = 0.0;     // m: slow down linearly inside this distance (0: never)
};

/// Heading error in (-pi, pi]: positive means the waypoint lies clockwise of the heading.
[[nodiscard]] double heading_error(const hal::Pose2& pose, const Waypoint& target) noexcept;

/// u = (kappa, v) towards `target`: kappa = gain * error (clamped), v shrinking linearly with
/// |error| from max_speed to min_speed at full_turn_error, and inside approach_radius.
[[nodiscard]] hal::DriveCommand move_to_waypoint(const hal::Pose2& pose, const Waypoint& target,
                                                 const MoveToWaypointParams& params) noexcept;

}  // namespace ringlet::behaviour
