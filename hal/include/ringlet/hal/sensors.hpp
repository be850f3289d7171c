#pragma once
// Everything the robot senses in one cycle, as plain fixed-size data (reading it never allocates),
// and the interface of whatever senses it.
#include <array>
#include <cstdint>

#include "ringlet/hal/geometry.hpp"
#include "ringlet/hal/time.hpp"

namespace ringlet::hal {

/// y = (x, y, theta), eq. (19): a GPS-like measurement of the robot's own pose.
struct PoseMeasurement {
  Nanos stamp{0};
  Pose2 pose{};
  bool valid = false;
};

/// Wheel odometry of the car-like base: distance travelled since start, and the measured
/// control u = (kappa, v) of eq. (17).
struct WheelOdometry {
  Nanos stamp{0};
  double distance = 0.0;   // metres, integrated, signed
  double velocity = 0.0;   // m/s
  double curvature = 0.0;  // 1/m
};

/// Head joint angles in radians: yaw positive to the left, pitch positive down.
struct HeadJoints {
  double yaw = 0.0;
  double pitch = 0.0;
};

/// The torso's tilt from the vertical, in radians, as an inertial unit measures it (the NAO's
/// InertialSensor AngleY and AngleX), both right-handed rotations in the robot frame:
///   pitch — about the robot's y axis (left): positive leans forward, so the head camera looks
///           further down (like a positive HeadJoints::pitch);
///   roll  — about the robot's x axis (ahead): positive lifts the left side, i.e. the torso leans
///           to its right.
/// The torso turns about the point on the ground under the robot's centre (the robot frame's
/// origin); hal/camera_geometry.hpp composes it with the head joints.
struct BodyTilt {
  double pitch = 0.0;
  double roll = 0.0;
};

/// The inertial unit's reading: the torso's tilt, stamped; invalid when the backend has no
/// inertial unit or could not read it (the tilt is then taken as zero: an upright torso).
struct InertialState {
  Nanos stamp{0};
  BodyTilt tilt{};
  bool valid = false;

  /// The tilt to use for the camera: the measured one, or upright when there is none.
  [[nodiscard]] BodyTilt tilt_or_upright() const noexcept { return valid ? tilt : BodyTilt{}; }
};

struct PowerState {
  double battery_volts = 0.0;
  double bus_volts = 0.0;
};

/// A planar range scan, eq. (20): beam i looks at angle `angle_min + i * angle_increment` in the
/// robot frame (0 = straight ahead, positive towards the robot's right, like theta). A beam is
/// valid when an occupied point lies within the maximum range Delta; an invalid beam is the
/// paper's phi (nothing seen), never a fake range.
struct LaserScan {
  static constexpr std::size_t kMaxBeams = 721;

  Nanos stamp{0};
  std::uint16_t beam_count = 0;
  double angle_min = 0.0;
  double angle_increment = 0.0;
  double max_range = 0.0;  // Delta, metres
  std::array<float, kMaxBeams> range{};
  std::array<bool, kMaxBeams> valid{};

  [[nodiscard]] double beam_angle(std::size_t i) const noexcept {
    return angle_min + static_cast<double>(i) * angle_increment;
  }
};

/// One cycle's sensor reading, filled by the backend in place.
struct SensorFrame {
  Nanos stamp{0};
  PoseMeasurement pose{};
  WheelOdometry odometry{};
  HeadJoints head{};
  InertialState body{};  // the torso's pitch and roll
  PowerState power{};
  LaserScan laser{};
  bool collided = false;  // the base's bumper: touching an obstacle right now
};

class Sensors {
 public:
  virtual ~Sensors() = default;
  /// Fills `out` with this cycle's readings. Called once per executive frame by the sense task;
  /// a lockstep simulator advances its world by exactly one period here. Returns false when the
  /// hardware could not be read (the frame's readings are then stale and marked invalid).
  virtual bool read(SensorFrame& out) noexcept = 0;
  /// True once the source has no more readings and never will (a replayed log's end): the
  /// firmware then ends the run instead of driving on stale data.
  [[nodiscard]] virtual bool exhausted() const noexcept { return false; }
};

}  // namespace ringlet::hal
