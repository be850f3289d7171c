#pragma once
// Drives through an ordered goal sequence: a goal counts as reached when the robot comes within
// the tolerance of it; then the next one becomes the target. When the last is reached the
// mission is complete and the command is to stop.
#include <cstddef>
#include <span>
#include <vector>

#include "ringlet/behaviour/move_to_waypoint.hpp"

namespace ringlet::behaviour {

class WaypointMission {
 public:
  /// Copies the goals (start-up only); `tolerance` must be > 0.
  WaypointMission(std::span<const Waypoint> goals, double tolerance, const MoveToWaypointParams& params);

  /// Advances past every goal the pose is within tolerance of, then returns the command. No
  /// allocation: runs in the cycle.
  hal::DriveCommand update(const hal::Pose2& pose) noexcept;

  [[nodiscard]] std::size_t goals_reached() const noexcept { return next_; }
  [[nodiscard]] std::size_t goal_count() const noexcept { return goals_.size(); }
  [[nodiscard]] bool complete() const noexcept { return next_ == goals_.size(); }
  /// The current target, or nullptr when complete.
  [[nodiscard]] const Waypoint* target() const noexcept { return complete() ? nullptr : &goals_[next_]; }

 private:
  std::vector<Waypoint> goals_;
  double tolerance_;
  MoveToWaypointParams params_;
  std::size_t next_ = 0;
};

}  // namespace ringlet::behaviour
