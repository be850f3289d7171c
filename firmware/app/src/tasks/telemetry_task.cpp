#include "ringlet/firmware/tasks/telemetry_task.hpp"

namespace ringlet::firmware {

std::unique_ptr<executive::Task> TelemetryTask::make(TaskServices& services) {
  return std::make_unique<TelemetryTask>(services.telemetry, services.board, services.config.trajectory_every);
}

void TelemetryTask::run(const executive::TaskContext& ctx) noexcept {
  const auto pose_msg = board_.get<wb::Pose>();
  const auto body = board_.get<wb::BodyState>();
  const auto status = board_.get<wb::MissionStatus>();
  const hal::Pose2 pose{pose_msg.x, pose_msg.y, pose_msg.theta};
  if (pose_msg.valid && ctx.frame % every_ == 0) telemetry_.record_pose(pose);
  if (body.bumper && !was_touching_) telemetry_.record_collision(pose);
  was_touching_ = body.bumper;
  telemetry_.record_odometry(body.odometry_distance);
  telemetry_.record_progress(status.reached, status.goal_count, ctx.frame);
  if (status.done) {
    telemetry_.record_pose(pose);  // end the trajectory where the mission ended
    ctx.request_stop();
  }
}

}  // namespace ringlet::firmware
