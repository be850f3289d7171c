// The lockstep simulated robot: read() moves the world one period and measures it; write() only
// stores the command that the next read() will apply. Nothing here allocates after construction.
#include "ringlet/sim_hal/sim_robot.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "number_text.hpp"
#include "ringlet/sim_hal/collision.hpp"

namespace ringlet::sim_hal {
namespace {

/// Battery model: a linear drain with distance driven, and a fixed drop to the bus behind it.
constexpr double kBatteryVoltsPerMetre = 0.01;
constexpr double kBusDropVolts = 0.2;

/// A bumped robot stops at its last free pose, up to one step of travel short of the obstacle.
/// The bumper stays pressed until it has backed off by more than that (plus a micrometre for the
/// boundary case), so that creeping forward again is the same contact, not a new one.
double contact_release_distance(const SimConfig& config) noexcept {
  return config.limits.max_speed * hal::to_seconds(config.period) + 1e-6;
}

/// Moves `current` towards `target` by at most `max_change`; a non-finite target holds still.
double approach(double current, double target, double max_change) noexcept {
  if (!std::isfinite(target)) return current;
  return current + std::clamp(target - current, -max_change, max_change);
}

/// The sway's starting phase in [0, 2π), from the seed by SplitMix64's finaliser: deterministic
/// on every host and independent of the noise RNG's stream.
std::uint64_t split_mix(std::uint64_t seed) noexcept {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

double sway_phase(std::uint64_t seed) noexcept {
  const std::uint64_t z = split_mix(seed);
  return 2.0 * std::numbers::pi * static_cast<double>(z >> 11) * 0x1.0p-53;
}

}  // namespace

SimRobot::SimRobot(World world, const SimConfig& config)
    : world_(std::move(world)),
      config_(config),
      rng_(config.seed),
      odometry_rng_(split_mix(split_mix(config.seed))),
      sway_phase_(sway_phase(config.seed)) {
  validate(config_);
  rays_.reserve(world_);
  body_ = {config_.body.pitch, config_.body.roll};
  state_.pose = world_.start;
  if (disc_collides(world_, Vec2{state_.pose.x, state_.pose.y}, config_.robot_radius)) {
    throw std::invalid_argument("start pose (" + detail::format_number(state_.pose.x) + ", " +
                                detail::format_number(state_.pose.y) +
                                ") collides with an obstacle or the bounds");
  }
  if (config_.kidnap.enabled && disc_collides(world_, Vec2{config_.kidnap.to.x, config_.kidnap.to.y}, config_.robot_radius)) {
    throw std::invalid_argument("kidnap pose (" + detail::format_number(config_.kidnap.to.x) + ", " +
                                detail::format_number(config_.kidnap.to.y) +
                                ") collides with an obstacle or the bounds");
  }
  if (config_.camera.enabled) camera_ = std::make_unique<SimCamera>(world_, config_.camera, config_.seed);
}

SimRobot::~SimRobot() = default;

const FrameTruth* SimRobot::camera_truth() const noexcept { return camera_ ? camera_->latest_truth() : nullptr; }

bool SimRobot::read(hal::SensorFrame& out) noexcept {
  step();
  // The camera sees the true state at the end of the step (before any measurement noise).
  if (camera_) camera_->on_step(steps_, time_, state_.pose, hal::CameraPosture{body_, head_});
  measure(out);
  return true;
}

void SimRobot::write(const hal::ActuatorCommand& cmd) noexcept {
  if (safe_.load(std::memory_order_acquire)) return;
  command_ = cmd;
}

bool SimRobot::read(hal::BallSighting& out) noexcept {
  const auto ball = true_ball_in_robot_frame();
  out.stamp = time_;
  out.seen = ball.has_value();
  out.at = ball.value_or(hal::RobotPoint{});
  return true;
}

std::optional<hal::RobotPoint> SimRobot::true_ball_in_robot_frame() const noexcept {
  if (!world_.ball) return std::nullopt;
  return hal::to_robot_frame(state_.pose, world_.ball->position.x, world_.ball->position.y);
}

void SimRobot::enter_safe_state() noexcept { safe_.store(true, std::memory_order_release); }

bool SimRobot::in_safe_state() const noexcept { return safe_.load(std::memory_order_acquire); }

void SimRobot::step() noexcept {
  const double dt = hal::to_seconds(config_.period);
  const bool safe = safe_.load(std::memory_order_acquire);
  if (config_.kidnap.enabled && !kidnapped_ && hal::to_seconds(time_) >= config_.kidnap.at_s) {
    kidnapped_ = true;  // picked up and put down: no distance driven, no odometry, no contact
    state_.pose = config_.kidnap.to;
    state_.velocity = 0.0;
    in_contact_ = false;
  }

  // Safe state: the drive is commanded to stop with the steering where it is. The speed still
  // falls at the acceleration limit, as a real drive's would; it does not vanish in one step.
  const hal::DriveCommand drive = safe ? hal::DriveCommand{state_.curvature, 0.0} : command_.drive;
  const CarState next = step_car(state_, drive, config_.limits, dt);

  if (disc_collides(world_, Vec2{next.pose.x, next.pose.y}, config_.robot_radius)) {
    // Blocked: stay at the last free pose, wheels stopped. One contact is one event however
    // long the controller keeps pushing.
    state_.velocity = 0.0;
    state_.curvature = next.curvature;
    if (!in_contact_) {
      ++collisions_;
      in_contact_ = true;
    }
  } else {
    const double travelled = next.velocity * dt;
    distance_ += std::fabs(travelled);
    // The wheels' count: scaled, and slipping as a random walk of variance slip² per metre.
    const SimOdometryError& e = config_.odometry;
    const double slip = e.slip_sigma > 0.0
                            ? e.slip_sigma * std::sqrt(std::fabs(travelled)) * odometry_normal_(odometry_rng_)
                            : 0.0;
    odometry_distance_ += travelled * e.scale + slip;
    state_ = next;
    if (in_contact_ && !disc_collides(world_, Vec2{state_.pose.x, state_.pose.y},
                                      config_.robot_radius + contact_release_distance(config_))) {
      in_contact_ = false;
    }
  }

  if (!safe) {
    const double max_change = config_.head_max_rate * dt;
    head_.yaw = approach(head_.yaw, command_.head.yaw, max_change);
    head_.pitch = approach(head_.pitch, command_.head.pitch, max_change);
  }

  time_ += config_.period;
  ++steps_;

  // The torso: its static lean, and a sway that grows with the speed. Skipped when there is no
  // sway, so that an upright robot's tilt stays exactly the configured constants.
  const SimBodyTilt& b = config_.body;
  if (b.sway_pitch != 0.0 || b.sway_roll != 0.0) {
    const double speed = std::min(1.0, std::fabs(state_.velocity) / config_.limits.max_speed);
    const double phase = sway_phase_ + 2.0 * std::numbers::pi * hal::to_seconds(time_) / b.sway_period;
    body_.pitch = b.pitch + b.sway_pitch * speed * std::sin(2.0 * phase);
    body_.roll = b.roll + b.sway_roll * speed * std::sin(phase);
  }
}

void SimRobot::measure(hal::SensorFrame& out) noexcept {
  // Noise is drawn only for a non-zero sigma, always in this order: x, y, theta, then one draw
  // per laser hit in beam order. Same world, config and seed therefore give the same frames.
  const auto noise = [this](double sigma) { return sigma > 0.0 ? sigma * unit_normal_(rng_) : 0.0; };
  const hal::Pose2& pose = state_.pose;

  out.stamp = time_;

  out.pose.stamp = time_;
  out.pose.pose.x = pose.x + noise(config_.gps_sigma_xy);
  out.pose.pose.y = pose.y + noise(config_.gps_sigma_xy);
  out.pose.pose.theta = hal::wrap_angle(pose.theta + noise(config_.gps_sigma_theta));
  out.pose.valid = true;

  out.odometry.stamp = time_;
  out.odometry.distance = odometry_distance_;
  const SimOdometryError& e = config_.odometry;
  out.odometry.velocity = state_.velocity * e.scale;
  out.odometry.curvature = state_.curvature;  // exact unless configured (and −0 stays −0)
  if (e.curvature_bias != 0.0) out.odometry.curvature += e.curvature_bias;
  if (e.curvature_sigma > 0.0) out.odometry.curvature += e.curvature_sigma * odometry_normal_(odometry_rng_);

  out.head = head_;

  out.body.stamp = time_;
  out.body.tilt = body_;
  out.body.valid = true;

  out.power.battery_volts = std::max(0.0, config_.battery_volts - kBatteryVoltsPerMetre * distance_);
  out.power.bus_volts = std::max(0.0, out.power.battery_volts - kBusDropVolts);

  hal::LaserScan& scan = out.laser;
  const auto beams = static_cast<std::size_t>(config_.laser_beams);
  scan.stamp = time_;
  scan.beam_count = static_cast<std::uint16_t>(beams);
  scan.angle_min = beams == 1 ? 0.0 : -0.5 * config_.laser_fov;
  scan.angle_increment = beams == 1 ? 0.0 : config_.laser_fov / static_cast<double>(beams - 1);
  scan.max_range = config_.laser_range;
  const Vec2 origin{pose.x, pose.y};
  rays_.select(world_, origin, config_.laser_range);
  for (std::size_t i = 0; i < beams; ++i) {
    const double hit = rays_.cast(world_, origin, pose.theta + scan.beam_angle(i), config_.laser_range);
    if (std::isfinite(hit)) {
      const double noisy = std::clamp(hit + noise(config_.laser_sigma), 0.0, config_.laser_range);
      scan.range[i] = static_cast<float>(noisy);
      scan.valid[i] = true;
    } else {
      scan.range[i] = 0.0F;  // nothing seen: phi of eq. (20), never a fake range
      scan.valid[i] = false;
    }
  }
  // Unused slots are cleared so a frame never carries a stale reading from an earlier scan.
  std::fill(scan.range.begin() + static_cast<std::ptrdiff_t>(beams), scan.range.end(), 0.0F);
  std::fill(scan.valid.begin() + static_cast<std::ptrdiff_t>(beams), scan.valid.end(), false);

  out.collided = in_contact_;
}

}  // namespace ringlet::sim_hal
