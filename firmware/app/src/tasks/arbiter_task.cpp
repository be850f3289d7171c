#include "ringlet/firmware/tasks/arbiter_task.hpp"

#include <algorithm>
#include <cmath>


namespace ringlet::firmware {

namespace reactive = behaviour::reactive;

std::unique_ptr<executive::Task> ArbiterTask::make(TaskServices& services) {
  return std::make_unique<ArbiterTask>(services.config.reactive, services.board);
}

void ArbiterTask::run(const executive::TaskContext& /*ctx*/) noexcept {
  const wb::Pose pose = board_.get<wb::Pose>();
  const wb::Plan plan = board_.get<wb::Plan>();
  const wb::LaserScan scan = board_.get<wb::LaserScan>();
  // The scan's points in the robot frame (x ahead, y left); the beams' angles are theta's sense.
  obstacles_.count = 0;
  const std::size_t beams = std::min<std::size_t>(scan.beam_count, scan.range_mm.size());
  std::size_t near = 0;
  const double reach = params_.lookahead + params_.robot_radius + params_.margin + params_.congestion_margin;
  for (std::size_t i = 0; i < beams; ++i) {
    if (scan.range_mm[i] == 0) continue;
    const double a = scan.angle_min + static_cast<double>(i) * scan.angle_increment;
    const double r = scan.range_mm[i] * 1e-3;
    obstacles_.point[obstacles_.count++] = {r * std::cos(a), -r * std::sin(a)};
    if (r <= reach) ++near;
  }
  out_.valid = pose.valid && plan.has_plan;
  const hal::Pose2 at{pose.x, pose.y, pose.theta};
  // Without a plan the votes are still computed (straight ahead), for the picture; not driven.
  const hal::RobotPoint waypoint = out_.valid ? hal::to_robot_frame(at, plan.waypoint_x, plan.waypoint_y) : hal::RobotPoint{1.0, 0.0};
  out_.heading_error = reactive::heading_error_to(waypoint);
  reactive::reactive_step(params_, waypoint, obstacles_, step_);
  const reactive::ArbiterDecision& d = step_.decision;
  out_.arc = static_cast<std::uint8_t>(d.arc);
  out_.curvature = out_.valid ? d.curvature : 0.0;
  out_.velocity = out_.valid ? d.speed : 0.0;
  out_.arc_count = static_cast<std::uint8_t>(params_.arcs.count);
  const auto& v = step_.votes;
  for (int i = 0; i < params_.arcs.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    out_.arc_curvature[k] = params_.arcs.curvature(i);
    out_.waypoint_vote[k] = v[static_cast<std::size_t>(reactive::Behaviour::kMoveToWaypoint)].vote[k];
    out_.avoid_vote[k] = v[static_cast<std::size_t>(reactive::Behaviour::kAvoidObstacles)].vote[k];
    out_.headway_speed[k] = v[static_cast<std::size_t>(reactive::Behaviour::kMaintainHeadway)].max_speed[k];
    out_.congestion_speed[k] = v[static_cast<std::size_t>(reactive::Behaviour::kSlowForCongestion)].max_speed[k];
    out_.turn_speed[k] = v[static_cast<std::size_t>(reactive::Behaviour::kSlowForTurns)].max_speed[k];
    out_.total_vote[k] = d.total[k];
  }
  board_.post(out_);
  cost_ = kBaseCost + kCostPerTest * static_cast<long>(2 * near * static_cast<std::size_t>(params_.arcs.count));
}

}  // namespace ringlet::firmware
