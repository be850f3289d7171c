#include "ringlet/behaviour/waypoint_mission.hpp"

#include <cmath>
#include <stdexcept>

namespace ringlet::behaviour {

WaypointMission::WaypointMission(std::span<const Waypoint> goals, double tolerance,
                                 const MoveToWaypointParams& params)
    : goals_(goals.begin(), goals.end()), tolerance_(tolerance), params_(params) {
  if (!(tolerance > 0.0)) throw std::invalid_argument("goal tolerance must be > 0");
}

hal::DriveCommand WaypointMission::update(const hal::Pose2& pose) noexcept {
  while (next_ < goals_.size() &&
         std::hypot(goals_[next_].x - pose.x, goals_[next_].y - pose.y) <= tolerance_) {
    ++next_;
  }
  if (complete()) return {0.0, 0.0};
  return move_to_waypoint(pose, goals_[next_], params_);
}

}  // namespace ringlet::behaviour
