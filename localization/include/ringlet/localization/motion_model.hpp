#pragma once
// Odometry for the filter. The base reports the signed distance it has driven and its curvature
// (hal::WheelOdometry, on the whiteboard as BodyState); OdometryIntegrator dead-reckons them into
// a pose in its own odometry frame, and the motion between two such poses, expressed in the frame
// of the first (forward, left, turn), is what the filter applies to every particle with noise
// proportional to it. Latency: the same relative motion takes an observation made at an earlier
// capture time into the robot frame of now.
#include "ringlet/hal/geometry.hpp"
#include "ringlet/hal/splitmix64.hpp"

namespace ringlet::localization {

/// A motion in the robot frame of its start: ahead, to the left (m), and the heading change (rad,
/// positive clockwise as hal::Pose2's theta).
struct OdometryDelta {
  double forward = 0.0;
  double left = 0.0;
  double turn = 0.0;
};

/// The motion from `from` to `to` (both in one frame), in the robot frame of `from`.
[[nodiscard]] OdometryDelta delta_between(const hal::Pose2& from, const hal::Pose2& to) noexcept;
/// `pose` moved by `d` (d in pose's robot frame).
[[nodiscard]] hal::Pose2 apply(const hal::Pose2& pose, const OdometryDelta& d) noexcept;
/// A robot-frame point of the start of `d` seen from its end.
[[nodiscard]] hal::RobotPoint transform_point(const OdometryDelta& d, double x, double y) noexcept;

/// Noise of the odometry, per unit of motion (Thrun, Burgard and Fox's α parameters).
struct MotionNoise {
  double forward_per_m = 0.10;    // σ of the distance per metre driven
  double side_per_m = 0.03;       // σ sideways per metre (slip)
  double turn_per_rad = 0.10;     // σ of the turn per radian turned
  double turn_per_m = 0.05;       // rad of heading error per metre driven
  double floor_xy = 0.002;        // m per update even standing still: keeps the cloud alive
  double floor_turn = 0.002;      // rad per update
};

/// `d` with noise drawn from `rng` (three draws, always in this order: forward, left, turn).
[[nodiscard]] OdometryDelta noisy(const OdometryDelta& d, const MotionNoise& noise, hal::SplitMix64& rng) noexcept;

/// Dead reckoning from the base's odometry: each sample's distance increment driven along an arc
/// of the sampled curvature (θ' = vκ, hal/geometry.hpp).
class OdometryIntegrator {
 public:
  /// Adds a sample of the cumulative distance (m) and the curvature (1/m) driven since the last.
  void add(double distance, double curvature) noexcept;
  [[nodiscard]] const hal::Pose2& pose() const noexcept { return pose_; }
  [[nodiscard]] bool started() const noexcept { return started_; }

 private:
  hal::Pose2 pose_{};
  double last_distance_ = 0.0;
  bool started_ = false;
};

}  // namespace ringlet::localization
