#pragma once
// Car-like kinematics exactly as Powers & Balch eq. (18):
//   x' = v sin(theta),  y' = v cos(theta),  theta' = v kappa
// integrated in closed form over one step with u = (kappa, v) held constant, after the command
// has been clamped to the limits and rate-limited.
#include "ringlet/hal/actuators.hpp"
#include "ringlet/hal/geometry.hpp"

namespace ringlet::sim_hal {

struct CarLimits {
  double max_speed = 1.0;           // m/s, |v| <= max_speed
  double max_curvature = 2.0;       // 1/m, |kappa| <= max_curvature
  double max_acceleration = 1.0;    // m/s^2, |dv/dt|
  double max_curvature_rate = 4.0;  // 1/(m s), |dkappa/dt|
};

struct CarState {
  hal::Pose2 pose{};
  double velocity = 0.0;
  double curvature = 0.0;
};

/// Exact solution of eq. (18) after `dt` seconds with constant kappa and v.
[[nodiscard]] hal::Pose2 integrate_arc(const hal::Pose2& start, double curvature, double velocity, double dt) noexcept;

/// One step: clamp the command to the limits, move v and kappa towards it no faster than the rate
/// limits allow, then integrate the arc with the new (kappa, v).
[[nodiscard]] CarState step_car(const CarState& state, const hal::DriveCommand& command, const CarLimits& limits,
                                double dt) noexcept;

}  // namespace ringlet::sim_hal
