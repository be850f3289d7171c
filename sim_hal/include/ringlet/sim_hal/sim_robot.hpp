#pragma once
// The simulated robot: a hal::Robot backend over a World. Lockstep: every Sensors::read() advances
// the world by exactly one executive period, then measures it, so a run depends only on the
// world, the configuration and the seed — never on how fast the host is or which clock paces it.
// One seeded RNG (std::mt19937_64) feeds all noise. The optional camera renders on its own thread
// with one camera period of latency, so it stays deterministic too (sim_camera.hpp).
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <random>

#include "ringlet/hal/robot.hpp"
#include "ringlet/sim_hal/kinematics.hpp"
#include "ringlet/sim_hal/sim_camera.hpp"
#include "ringlet/sim_hal/collision.hpp"
#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal {

/// The torso's tilt (hal::BodyTilt conventions, rad): a static lean, plus a sway while driving, as
/// a walking NAO's torso rocks with its steps. The sway's amplitude grows with the speed
/// (|v| / limits.max_speed); roll swings once per `sway_period`, pitch twice (one step each side),
/// from a phase drawn from the seed (a hash, not the noise RNG: the other sensors' noise stays the
/// same whether or not the torso sways). The inertial unit reports the true tilt (no noise, no
/// bias) and the camera renders from it. All zero by default: an upright robot.
struct SimBodyTilt {
  double pitch = 0.0;        // rad, positive leans forward
  double roll = 0.0;         // rad, positive leans right
  double sway_pitch = 0.0;   // rad, amplitude at full speed
  double sway_roll = 0.0;    // rad, amplitude at full speed
  double sway_period = 1.0;  // s, one left-right cycle
};

/// Wheel odometry's errors, as a real base has them: a scale error (wheels not quite their nominal
/// size), a curvature bias (steering not quite centred), slip (a random walk: the distance's error
/// has variance slip_sigma² per metre driven) and noise on each measured curvature. All off by
/// default: the odometry is then exact. Drawn from their own stream, so turning them on changes
/// nothing but the odometry.
struct SimOdometryError {
  double scale = 1.0;            // measured distance / true distance
  double curvature_bias = 0.0;   // 1/m, added to every measured curvature
  double slip_sigma = 0.0;       // m/√m
  double curvature_sigma = 0.0;  // 1/m, per reading
};

/// A referee's pick-up: at `at_s` of simulated time the robot is lifted and put down at `to`,
/// standing (speed 0, steering as it was); odometry does not see it. Deterministic.
struct SimKidnap {
  bool enabled = false;
  double at_s = 0.0;
  hal::Pose2 to{};
};

struct SimConfig {
  hal::Nanos period{10'000'000};  // one executive period per read()
  std::uint64_t seed = 1;
  CarLimits limits{};
  double robot_radius = 0.25;     // m, the footprint used for collisions
  double gps_sigma_xy = 0.0;      // m, Gaussian noise on the GPS pose (eq. 19)
  double gps_sigma_theta = 0.0;   // rad
  SimOdometryError odometry{};    // exact by default
  int laser_beams = 181;          // N, at most hal::LaserScan::kMaxBeams
  double laser_fov = 3.14159265358979323846;  // rad, centred straight ahead
  double laser_range = 8.0;       // Delta, m
  double laser_sigma = 0.0;       // m, Gaussian noise on valid ranges
  double head_max_rate = 4.0;     // rad/s the simulated head joints can move
  double battery_volts = 12.6;    // start voltage; drains slowly with distance driven
  SimBodyTilt body{};             // the torso's tilt (upright by default)
  SimCameraConfig camera{};       // off by default: rendering needs a thread and a few ms a frame
  SimKidnap kidnap{};             // off by default
};

/// Throws std::invalid_argument naming the field when a value is out of range (the camera's
/// fields only when it is enabled).
void validate(const SimConfig& config);

class SimRobot : public hal::Robot, private hal::Sensors, private hal::Actuators, private hal::BallSensor {
 public:
  /// Validates the configuration and checks the start pose is collision-free (throws otherwise).
  SimRobot(World world, const SimConfig& config);
  ~SimRobot() override;  // joins the camera's render thread, if any
  SimRobot(const SimRobot&) = delete;
  SimRobot& operator=(const SimRobot&) = delete;

  // hal::Robot
  [[nodiscard]] std::string_view backend_name() const noexcept override { return "sim"; }
  hal::Sensors& sensors() noexcept override { return *this; }
  hal::Actuators& actuators() noexcept override { return *this; }
  /// The simulated head camera when SimConfig::camera.enabled, otherwise null.
  hal::Camera* camera() noexcept override { return camera_.get(); }
  /// An idealised ball detector: where the world's ball really is (seen when the world has one).
  hal::BallSensor* ball_sensor() noexcept override { return this; }

  // Ground truth, for telemetry, pictures and tests (never for the controller's logic).
  [[nodiscard]] const World& world() const noexcept { return world_; }
  [[nodiscard]] const CarState& true_state() const noexcept { return state_; }
  [[nodiscard]] hal::Nanos sim_time() const noexcept { return time_; }
  [[nodiscard]] std::uint64_t steps() const noexcept { return steps_; }
  [[nodiscard]] std::uint64_t collisions() const noexcept { return collisions_; }  // contact events
  [[nodiscard]] double distance_travelled() const noexcept { return distance_; }
  /// The torso's true tilt now (what the inertial unit reports and the camera renders from).
  [[nodiscard]] const hal::BodyTilt& true_body_tilt() const noexcept { return body_; }
  [[nodiscard]] const SimConfig& config() const noexcept { return config_; }
  /// Where the world's ball really is in the robot frame (none when the world has no ball).
  [[nodiscard]] std::optional<hal::RobotPoint> true_ball_in_robot_frame() const noexcept;
  /// Ground truth of the camera frame grab_latest() returns now (null without a camera or before
  /// the first frame is delivered). Sim-only: valid until the next read().
  [[nodiscard]] const FrameTruth* camera_truth() const noexcept;
  /// The simulated camera itself (null when disabled), for its sim-only statistics.
  [[nodiscard]] const SimCamera* sim_camera() const noexcept { return camera_.get(); }

 private:
  // hal::Sensors
  bool read(hal::SensorFrame& out) noexcept override;
  // hal::BallSensor
  bool read(hal::BallSighting& out) noexcept override;
  // hal::Actuators
  void write(const hal::ActuatorCommand& cmd) noexcept override;
  void enter_safe_state() noexcept override;
  [[nodiscard]] bool in_safe_state() const noexcept override;

  void step() noexcept;
  void measure(hal::SensorFrame& out) noexcept;

  World world_;
  RayCandidates rays_;  // the obstacles within the laser's range, chosen once per scan
  SimConfig config_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> unit_normal_{0.0, 1.0};
  std::mt19937_64 odometry_rng_;  // the odometry's errors: a stream of their own
  std::normal_distribution<double> odometry_normal_{0.0, 1.0};
  CarState state_{};
  hal::HeadJoints head_{};
  hal::BodyTilt body_{};
  double sway_phase_ = 0.0;  // rad, from the seed
  hal::ActuatorCommand command_{};
  std::atomic<bool> safe_{false};
  bool in_contact_ = false;
  bool kidnapped_ = false;
  hal::Nanos time_{0};
  std::uint64_t steps_ = 0;
  std::uint64_t collisions_ = 0;
  double distance_ = 0.0;           // path length driven, |v| dt summed: battery drain, statistics
  double odometry_distance_ = 0.0;  // v dt summed (with the odometry's errors), signed like hal::WheelOdometry::distance
  std::unique_ptr<SimCamera> camera_;  // last: its thread starts once everything else exists
};

}  // namespace ringlet::sim_hal
