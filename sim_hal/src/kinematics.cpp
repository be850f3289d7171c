// Eq. (18) with u = (kappa, v) held over the step has the closed form
//   theta1 = theta0 + v kappa t
//   x1 = x0 + (cos theta0 - cos theta1) / kappa,   y1 = y0 + (sin theta1 - sin theta0) / kappa.
// Written with the sum-to-product identities this is, exactly,
//   x1 = x0 + s sin(theta_mid) sinc(dtheta / 2),   y1 = y0 + s cos(theta_mid) sinc(dtheta / 2)
// with s = v t, dtheta = kappa s and theta_mid = theta0 + dtheta / 2. That form has no 1/kappa to
// blow up, goes to the straight line x += s sin theta0, y += s cos theta0 as kappa -> 0 without a
// jump, and loses no precision to the cancellation in cos theta0 - cos theta1 on gentle arcs.
#include "ringlet/sim_hal/kinematics.hpp"

#include <algorithm>
#include <cmath>

namespace ringlet::sim_hal {
namespace {

/// sin(u) / u, with its Taylor series near 0 where the quotient would be 0/0. Below 1e-4 the first
/// omitted term (u^6 / 5040) is under 1e-27, far below double precision.
double sinc(double u) noexcept {
  if (std::fabs(u) < 1e-4) {
    const double u2 = u * u;
    return 1.0 - u2 / 6.0 + u2 * u2 / 120.0;
  }
  return std::sin(u) / u;
}

/// Moves `current` towards `target` by at most `max_change`.
double approach(double current, double target, double max_change) noexcept {
  return current + std::clamp(target - current, -max_change, max_change);
}

/// A non-finite command (a controller bug) must not poison the state: it is read as "stop, straight".
double finite_or_zero(double value) noexcept { return std::isfinite(value) ? value : 0.0; }

}  // namespace

hal::Pose2 integrate_arc(const hal::Pose2& start, double curvature, double velocity, double dt) noexcept {
  const double arc_length = velocity * dt;
  const double turn = curvature * arc_length;
  const double mid_heading = start.theta + 0.5 * turn;
  const double chord_scale = arc_length * sinc(0.5 * turn);
  return hal::Pose2{start.x + chord_scale * std::sin(mid_heading), start.y + chord_scale * std::cos(mid_heading),
                    hal::wrap_angle(start.theta + turn)};
}

CarState step_car(const CarState& state, const hal::DriveCommand& command, const CarLimits& limits,
                  double dt) noexcept {
  const double target_velocity =
      std::clamp(finite_or_zero(command.velocity), -limits.max_speed, limits.max_speed);
  const double target_curvature =
      std::clamp(finite_or_zero(command.curvature), -limits.max_curvature, limits.max_curvature);
  CarState next;
  next.velocity = approach(state.velocity, target_velocity, limits.max_acceleration * dt);
  next.curvature = approach(state.curvature, target_curvature, limits.max_curvature_rate * dt);
  next.pose = integrate_arc(state.pose, next.curvature, next.velocity, dt);
  return next;
}

}  // namespace ringlet::sim_hal
