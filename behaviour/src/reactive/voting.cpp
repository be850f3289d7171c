#include "ringlet/behaviour/reactive/voting.hpp"

#include <algorithm>
#include <cmath>

#include "ringlet/hal/portable_math.hpp"

namespace ringlet::behaviour::reactive {
namespace {

bool positive(double v) { return v > 0.0 && std::isfinite(v); }

void reset(const ReactiveParams& p, ArcVotes& out) noexcept {
  out.vote.fill(0.0);
  out.max_speed.fill(p.top_speed);
}

/// 0 at or below `lo`, 1 at or above `hi`, linear between.
double ramp(double x, double lo, double hi) noexcept {
  if (x <= lo) return 0.0;
  if (x >= hi) return 1.0;
  return (x - lo) / (hi - lo);
}

}  // namespace

std::string ReactiveParams::validate() const {
  if (std::string e = arcs.validate(); !e.empty()) return e;
  if (!positive(top_speed)) return "top_speed must be positive";
  if (!positive(robot_radius)) return "robot_radius must be positive";
  if (!(margin >= 0.0) || !std::isfinite(margin)) return "margin must not be negative";
  if (!positive(lookahead)) return "lookahead must be positive";
  if (!positive(waypoint_gain)) return "waypoint_gain must be positive";
  if (!positive(vote_width)) return "vote_width must be positive";
  if (!(stop_distance >= 0.0) || !(slow_distance > stop_distance) || !std::isfinite(slow_distance))
    return "slow_distance must be greater than stop_distance, which must not be negative";
  if (!(congestion_margin >= 0.0) || !std::isfinite(congestion_margin)) return "congestion_margin must not be negative";
  if (!(congested_speed > 0.0) || !(congested_speed <= top_speed)) return "congested_speed must be positive and at most top_speed";
  if (!positive(max_yaw_rate)) return "max_yaw_rate must be positive";
  for (int b = 0; b < kBehaviours; ++b)
    if (!(weight[static_cast<std::size_t>(b)] >= 0.0) || !std::isfinite(weight[static_cast<std::size_t>(b)]))
      return std::string("weights.") + kBehaviourNames[static_cast<std::size_t>(b)] + " must not be negative";
  return {};
}

double heading_error_to(const hal::RobotPoint& w) noexcept { return std::atan2(-w.y, w.x); }

void move_to_waypoint_votes(const ReactiveParams& p, const hal::RobotPoint& waypoint, ArcVotes& out) noexcept {
  reset(p, out);
  double target = std::clamp(p.waypoint_gain * heading_error_to(waypoint), -p.arcs.max_curvature, p.arcs.max_curvature);
  // The tightest circle on the waypoint's side: centre (0, ∓R) in the robot frame (right: −R).
  const double r = 1.0 / p.arcs.max_curvature;
  const double cy = waypoint.y < 0.0 ? -r : r;
  if (hal::portable_hypot(waypoint.x, waypoint.y - cy) < r) target = 0.0;
  for (int i = 0; i < p.arcs.count; ++i)
    out.vote[static_cast<std::size_t>(i)] = std::max(0.0, 1.0 - std::abs(p.arcs.curvature(i) - target) / p.vote_width);
}

void avoid_obstacles_votes(const ReactiveParams& p, const PerArc& clearance, ArcVotes& out) noexcept {
  reset(p, out);
  for (int i = 0; i < p.arcs.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    out.vote[k] = -(1.0 - std::min(clearance[k], p.lookahead) / p.lookahead);
  }
}

void maintain_headway_votes(const ReactiveParams& p, const PerArc& clearance, ArcVotes& out) noexcept {
  reset(p, out);
  for (int i = 0; i < p.arcs.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    out.max_speed[k] = p.top_speed * ramp(clearance[k], p.stop_distance, p.slow_distance);
  }
}

void slow_for_congestion_votes(const ReactiveParams& p, const PerArc& wide_clearance, ArcVotes& out) noexcept {
  reset(p, out);
  for (int i = 0; i < p.arcs.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (wide_clearance[k] >= p.lookahead) continue;  // not congested along this arc
    out.max_speed[k] = p.congested_speed + (p.top_speed - p.congested_speed) * wide_clearance[k] / p.lookahead;
  }
}

void slow_for_turns_votes(const ReactiveParams& p, ArcVotes& out) noexcept {
  reset(p, out);
  for (int i = 0; i < p.arcs.count; ++i) {
    const double kappa = std::abs(p.arcs.curvature(i));
    if (kappa > 0.0) out.max_speed[static_cast<std::size_t>(i)] = std::min(p.top_speed, p.max_yaw_rate / kappa);
  }
}

ArbiterDecision arbitrate(const ReactiveParams& p, const std::array<ArcVotes, kBehaviours>& votes) noexcept {
  ArbiterDecision d;
  PerArc speed{};
  bool any_moving = false;
  for (int i = 0; i < p.arcs.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    double sum = 0.0;
    speed[k] = p.top_speed;
    for (int b = 0; b < kBehaviours; ++b) {
      const ArcVotes& v = votes[static_cast<std::size_t>(b)];
      sum += p.weight[static_cast<std::size_t>(b)] * v.vote[k];
      speed[k] = std::min(speed[k], v.max_speed[k]);
    }
    d.total[k] = sum;
    any_moving = any_moving || speed[k] > 0.0;
  }
  // A speed limit of 0 is a veto: an arc no behaviour lets the robot drive is not chosen while
  // another can be driven (the most-voted arc may end at an obstacle: stopping there for ever is
  // no choice). With every arc vetoed the most-voted one is chosen, at speed 0: the robot stops.
  for (int i = 0; i < p.arcs.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (any_moving && !(speed[k] > 0.0)) continue;
    const bool better = d.arc < 0 || d.total[k] > d.total[static_cast<std::size_t>(d.arc)] ||
                        (d.total[k] == d.total[static_cast<std::size_t>(d.arc)] &&
                         std::abs(p.arcs.curvature(i)) < std::abs(p.arcs.curvature(d.arc)));
    if (better) d.arc = i;
  }
  d.curvature = p.arcs.curvature(d.arc);
  d.speed = speed[static_cast<std::size_t>(d.arc)];
  return d;
}

void reactive_step(const ReactiveParams& p, const hal::RobotPoint& waypoint, const ObstaclePoints& obstacles,
                   ReactiveStep& out) noexcept {
  clearances(p.arcs, obstacles, p.robot_radius + p.margin, p.lookahead, out.clearance);
  clearances(p.arcs, obstacles, p.robot_radius + p.margin + p.congestion_margin, p.lookahead, out.wide_clearance);
  move_to_waypoint_votes(p, waypoint, out.votes[static_cast<std::size_t>(Behaviour::kMoveToWaypoint)]);
  avoid_obstacles_votes(p, out.clearance, out.votes[static_cast<std::size_t>(Behaviour::kAvoidObstacles)]);
  maintain_headway_votes(p, out.clearance, out.votes[static_cast<std::size_t>(Behaviour::kMaintainHeadway)]);
  slow_for_congestion_votes(p, out.wide_clearance, out.votes[static_cast<std::size_t>(Behaviour::kSlowForCongestion)]);
  slow_for_turns_votes(p, out.votes[static_cast<std::size_t>(Behaviour::kSlowForTurns)]);
  out.decision = arbitrate(p, out.votes);
}

}  // namespace ringlet::behaviour::reactive
