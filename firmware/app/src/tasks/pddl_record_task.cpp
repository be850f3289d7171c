#include "ringlet/firmware/tasks/pddl_record_task.hpp"

#include <algorithm>

namespace ringlet::firmware {

std::unique_ptr<executive::Task> PddlRecordTask::make(TaskServices& services) {
  // No map: the plans are drawn over the world alone (cell 0), with the problem's places.
  PlanTrack& track = services.telemetry.enable_plans(hal::PlanPicture{}, 0, kMaxPlans, kMaxPointsPerPlan);
  track.reported.reserve(kMaxReportedObstacles);
  for (const pddl::Place& p : services.config.pddl.places) track.places.push_back({{p.x, p.y}, p.name});
  return std::make_unique<PddlRecordTask>(services.telemetry, services.board);
}

void PddlRecordTask::on_reply(const wb::PddlReply& reply) noexcept {
  if (reply.op != wb::PddlOp::kNextAction || !reply.ok || reply.plan == 0) return;
  // The machine asks for the ranks in order; a repeated or stale answer extends nothing.
  if (reply.plan != plan_) {
    if (reply.rank != 0) return;
    plan_ = reply.plan;
    next_rank_ = 0;
  }
  if (reply.rank != next_rank_) return;
  ++next_rank_;
  // A navigation action names where it starts and where it ends (drive robot from to): the first
  // action starts the polyline at its first place, every action extends it to its last.
  const std::size_t n = std::min<std::size_t>(reply.arg_count, reply.arg_place.size());
  std::size_t first = n, last = n;
  for (std::size_t i = 0; i < n; ++i) {
    if (reply.arg_place[i] == 0) continue;
    if (first == n) first = i;
    last = i;
  }
  if (first == n) return;
  const hal::WorldPoint to{reply.arg_x[last], reply.arg_y[last]};
  if (reply.rank == 0) {
    const hal::WorldPoint path[2] = {{reply.arg_x[first], reply.arg_y[first]}, to};
    telemetry_.record_plan(std::span<const hal::WorldPoint>(path, first == last ? 1 : 2));
  } else {
    telemetry_.extend_last_plan(to);
  }
}

void PddlRecordTask::on_request(const wb::PddlRequest& request) noexcept {
  if (request.op != wb::PddlOp::kIsObstacleKnown) return;
  if (have_obstacle_id_ && request.id <= last_obstacle_id_) return;  // the same request again
  have_obstacle_id_ = true;
  last_obstacle_id_ = request.id;
  telemetry_.record_reported_obstacle({request.x, request.y});
}

void PddlRecordTask::run(const executive::TaskContext& /*ctx*/) noexcept {
  const auto missed = [this](std::uint64_t n) { telemetry_.record_missed_plans(n); };
  board_.read_since<wb::PddlRequest>(requests_seen_, [this](const wb::PddlRequest& m) { on_request(m); }, missed);
  board_.read_since<wb::PddlReply>(replies_seen_, [this](const wb::PddlReply& m) { on_reply(m); }, missed);
}

}  // namespace ringlet::firmware
