#include "ringlet/firmware/telemetry.hpp"

#include <algorithm>
#include <cmath>

#include "ringlet/firmware/config.hpp"

namespace ringlet::firmware {

Telemetry::Telemetry(std::size_t trajectory_capacity, std::size_t collision_capacity, std::size_t goal_count) {
  // The configuration refuses runs that need more; the cap here keeps a stack built from any
  // other config (a test, a tool) from reserving without limit.
  trajectory_.reserve(std::min<std::size_t>(trajectory_capacity, kMaxTrajectorySamples));
  collision_points_.reserve(collision_capacity);
  goal_times_.reserve(goal_count);
}

// push_back below never reallocates: each is guarded by the capacity reserved at start-up.
void Telemetry::record_pose(const hal::Pose2& pose) noexcept {
  if (trajectory_.size() < trajectory_.capacity()) {
    trajectory_.push_back(pose);
  } else {
    ++dropped_;
  }
}

void Telemetry::record_collision(const hal::Pose2& pose) noexcept {
  ++collisions_;
  if (collision_points_.size() < collision_points_.capacity()) collision_points_.push_back({pose.x, pose.y});
}

void Telemetry::record_goal(std::size_t goals_reached, hal::Nanos when) noexcept {
  while (goal_times_.size() < goals_reached && goal_times_.size() < goal_times_.capacity()) goal_times_.push_back(when);
}

void Telemetry::record_head(const hal::HeadJoints& head, const hal::RobotPoint& true_ball, hal::Nanos when) noexcept {
  const double wanted = std::atan2(true_ball.y, true_ball.x);
  if (when < std::chrono::seconds{1} || std::abs(wanted) > HeadTracking::kNeckLimit) return;
  const double error = std::abs(hal::wrap_angle(head.yaw - wanted));
  ++head_.frames;
  if (error <= HeadTracking::kOnTarget) ++head_.on_target;
  head_.sum_error += error;
  head_.max_error = std::max(head_.max_error, error);
}

}  // namespace ringlet::firmware
