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
#include "ringlet/hal/time.hpp"

namespace ringlet::firmware {

struct CollisionPoint {
  double x = 0.0;
  double y = 0.0;
};

class Telemetry {
 public:
  Telemetry(std::size_t trajectory_capacity, std::size_t collision_capacity, std::size_t goal_count);

  void record_pose(const hal::Pose2& pose) noexcept;
  void record_collision(const hal::Pose2& pose) noexcept;
  void record_goal(std::size_t goals_reached, hal::Nanos when) noexcept;

  [[nodiscard]] std::span<const hal::Pose2> trajectory() const noexcept { return trajectory_; }
  [[nodiscard]] std::span<const CollisionPoint> collision_points() const noexcept { return collision_points_; }
  [[nodiscard]] std::uint64_t collisions() const noexcept { return collisions_; }
  [[nodiscard]] std::span<const hal::Nanos> goal_times() const noexcept { return goal_times_; }
  [[nodiscard]] std::uint64_t dropped_samples() const noexcept { return dropped_; }

 private:
  std::vector<hal::Pose2> trajectory_;
  std::vector<CollisionPoint> collision_points_;
  std::vector<hal::Nanos> goal_times_;
  std::uint64_t collisions_ = 0;
  std::uint64_t dropped_ = 0;
};

}  // namespace ringlet::firmware
