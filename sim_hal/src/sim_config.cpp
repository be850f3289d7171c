// Checks a SimConfig before a SimRobot is built from it, so a typo in the configuration file is a
// clear start-up error naming the field rather than a robot that silently behaves oddly.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>

#include "number_text.hpp"
#include "ringlet/sim_hal/sim_robot.hpp"

namespace ringlet::sim_hal {
namespace {

[[noreturn]] void reject(std::string_view field, std::string_view rule, const std::string& got) {
  throw std::invalid_argument("sim." + std::string(field) + " must be " + std::string(rule) + ", got " + got);
}

void require_positive(std::string_view field, double value) {
  if (!(std::isfinite(value) && value > 0.0)) reject(field, "finite and > 0", detail::format_number(value));
}

void require_non_negative(std::string_view field, double value) {
  if (!(std::isfinite(value) && value >= 0.0)) reject(field, "finite and >= 0", detail::format_number(value));
}

}  // namespace

void validate(const SimConfig& config) {
  if (config.period.count() <= 0) reject("period", "> 0 ns", std::to_string(config.period.count()) + " ns");
  require_positive("limits.max_speed", config.limits.max_speed);
  require_positive("limits.max_curvature", config.limits.max_curvature);
  require_positive("limits.max_acceleration", config.limits.max_acceleration);
  require_positive("limits.max_curvature_rate", config.limits.max_curvature_rate);
  require_positive("robot_radius", config.robot_radius);
  require_non_negative("gps_sigma_xy", config.gps_sigma_xy);
  require_non_negative("gps_sigma_theta", config.gps_sigma_theta);
  require_positive("odometry.scale", config.odometry.scale);
  require_non_negative("odometry.slip_sigma", config.odometry.slip_sigma);
  require_non_negative("odometry.curvature_sigma", config.odometry.curvature_sigma);
  constexpr int kMaxBeams = static_cast<int>(hal::LaserScan::kMaxBeams);
  if (config.laser_beams < 1 || config.laser_beams > kMaxBeams) {
    reject("laser_beams", "in 1.." + std::to_string(kMaxBeams), std::to_string(config.laser_beams));
  }
  constexpr double kFullCircle = 2.0 * std::numbers::pi;
  if (!(config.laser_fov > 0.0 && config.laser_fov <= kFullCircle)) {
    reject("laser_fov", "in (0, " + detail::format_number(kFullCircle) + "] rad", detail::format_number(config.laser_fov));
  }
  require_positive("laser_range", config.laser_range);
  require_non_negative("laser_sigma", config.laser_sigma);
  require_positive("head_max_rate", config.head_max_rate);
  require_non_negative("battery_volts", config.battery_volts);
  // Past these (hal::BodyTiltRange) the robot would be falling, not standing or walking; a lean
  // plus its sway must stay inside them too.
  const auto require_tilt = [](std::string_view field, double value, double max_deg) {
    const double max = max_deg * std::numbers::pi / 180.0;
    if (!(std::isfinite(value) && std::fabs(value) <= max)) {
      reject(field, "finite and within ±" + detail::format_number(max) + " rad (" + detail::format_number(max_deg) + "°)",
             detail::format_number(value));
    }
  };
  using Range = hal::BodyTiltRange;
  require_tilt("body.pitch", config.body.pitch, Range::kMaxPitchDeg);
  require_tilt("body.roll", config.body.roll, Range::kMaxRollDeg);
  require_tilt("body.sway_pitch", config.body.sway_pitch, Range::kMaxPitchDeg);
  require_tilt("body.sway_roll", config.body.sway_roll, Range::kMaxRollDeg);
  require_tilt("body.pitch + |sway_pitch|", std::fabs(config.body.pitch) + std::fabs(config.body.sway_pitch),
               Range::kMaxPitchDeg);
  require_tilt("body.roll + |sway_roll|", std::fabs(config.body.roll) + std::fabs(config.body.sway_roll),
               Range::kMaxRollDeg);
  if (!(std::isfinite(config.body.sway_period) && config.body.sway_period >= 0.05 && config.body.sway_period <= 60.0)) {
    reject("body.sway_period", "in [0.05, 60] s", detail::format_number(config.body.sway_period));
  }
  if (config.camera.enabled) validate(config.camera);
}

}  // namespace ringlet::sim_hal
