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
  if (config.camera.enabled) validate(config.camera);
}

}  // namespace ringlet::sim_hal
