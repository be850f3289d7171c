#pragma once
// The record of a run: the trajectory (sampled every N frames), where collisions happened, how
// many goals were reached and when. Buffers are sized at start-up for the longest run the
// configuration allows, so recording never allocates; samples beyond capacity are counted, not
// stored.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "ringlet/hal/geometry.hpp"
#include "ringlet/hal/sensors.hpp"
#include "ringlet/hal/time.hpp"

namespace ringlet::firmware {

struct CollisionPoint {
  double x = 0.0;
  double y = 0.0;
};

/// How well the head's measured yaw follows the true direction of the ball (sim only). Frames
/// where the ball lies beyond the neck's reach, and the first second (the head starts ahead), do
/// not count.
struct HeadTracking {
  static constexpr double kNeckLimit = 2.0;      // rad, as the ball tracker clamps
  static constexpr double kOnTarget = 0.0873;    // rad: 5 degrees
  std::uint64_t frames = 0;
  std::uint64_t on_target = 0;
  double sum_error = 0.0;  // rad
  double max_error = 0.0;  // rad

  [[nodiscard]] double on_target_share() const noexcept {
    return frames == 0 ? 0.0 : static_cast<double>(on_target) / static_cast<double>(frames);
  }
  [[nodiscard]] double mean_error() const noexcept {
    return frames == 0 ? 0.0 : sum_error / static_cast<double>(frames);
  }
};

class Telemetry {
 public:
  Telemetry(std::size_t trajectory_capacity, std::size_t collision_capacity, std::size_t goal_count);

  void record_pose(const hal::Pose2& pose) noexcept;
  void record_collision(const hal::Pose2& pose) noexcept;
  void record_goal(std::size_t goals_reached, hal::Nanos when) noexcept;
  void record_head(const hal::HeadJoints& head, const hal::RobotPoint& true_ball, hal::Nanos when) noexcept;

  [[nodiscard]] std::span<const hal::Pose2> trajectory() const noexcept { return trajectory_; }
  [[nodiscard]] std::span<const CollisionPoint> collision_points() const noexcept { return collision_points_; }
  [[nodiscard]] std::uint64_t collisions() const noexcept { return collisions_; }
  [[nodiscard]] std::span<const hal::Nanos> goal_times() const noexcept { return goal_times_; }
  [[nodiscard]] std::uint64_t dropped_samples() const noexcept { return dropped_; }
  [[nodiscard]] const HeadTracking& head_tracking() const noexcept { return head_; }

 private:
  std::vector<hal::Pose2> trajectory_;
  std::vector<CollisionPoint> collision_points_;
  std::vector<hal::Nanos> goal_times_;
  std::uint64_t collisions_ = 0;
  std::uint64_t dropped_ = 0;
  HeadTracking head_{};
};

}  // namespace ringlet::firmware
