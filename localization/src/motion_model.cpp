#include "ringlet/localization/motion_model.hpp"

#include <cmath>

#include "ringlet/localization/gaussian.hpp"

namespace ringlet::localization {

OdometryDelta delta_between(const hal::Pose2& from, const hal::Pose2& to) noexcept {
  const hal::RobotPoint p = hal::to_robot_frame(from, to.x, to.y);
  return {p.x, p.y, hal::wrap_angle(to.theta - from.theta)};
}

hal::Pose2 apply(const hal::Pose2& pose, const OdometryDelta& d) noexcept {
  const hal::WorldPoint at = hal::RobotToWorld(pose).point(d.forward, d.left);
  return {at.x, at.y, hal::wrap_angle(pose.theta + d.turn)};
}

hal::RobotPoint transform_point(const OdometryDelta& d, double x, double y) noexcept {
  // Put the start frame at the origin: the point in "world" = start frame, seen from the end pose.
  const hal::Pose2 end = apply(hal::Pose2{}, d);
  // hal::Pose2{} has theta 0: ahead is +y, left is −x, so the start frame's robot point (x, y)
  // sits at world (−y, x).
  return hal::to_robot_frame(end, -y, x);
}

OdometryDelta noisy(const OdometryDelta& d, const MotionNoise& n, hal::SplitMix64& rng) noexcept {
  const double dist = std::sqrt(d.forward * d.forward + d.left * d.left);
  const double turn = std::fabs(d.turn);
  const double sf = n.forward_per_m * dist + n.floor_xy;
  const double sl = n.side_per_m * dist + n.floor_xy;
  const double st = n.turn_per_rad * turn + n.turn_per_m * dist + n.floor_turn;
  const double ef = standard_normal(rng);
  const double el = standard_normal(rng);
  const double et = standard_normal(rng);
  return {d.forward + sf * ef, d.left + sl * el, d.turn + st * et};
}

void OdometryIntegrator::add(double distance, double curvature) noexcept {
  if (!started_) {
    started_ = true;
    last_distance_ = distance;
    return;
  }
  const double ds = distance - last_distance_;
  last_distance_ = distance;
  if (ds == 0.0 || !std::isfinite(ds) || !std::isfinite(curvature)) return;
  // Along the arc: the chord points at the mean heading, its length s·sinc(Δθ/2) ≈ s for the
  // small steps of one frame (10 ms; Δθ ≤ 0.02 rad at 1 m/s and κ = 2).
  const double turn = ds * curvature;
  const double mid = pose_.theta + 0.5 * turn;
  pose_.x += ds * std::sin(mid);
  pose_.y += ds * std::cos(mid);
  pose_.theta = hal::wrap_angle(pose_.theta + turn);
}

}  // namespace ringlet::localization
