#include "ringlet/firmware/tasks.hpp"

namespace ringlet::firmware {

void SenseTask::run(const executive::TaskContext& /*ctx*/) noexcept { state_.sensors_ok = sensors_.read(state_.sensors); }

void FollowTask::run(const executive::TaskContext& /*ctx*/) noexcept {
  if (state_.sensors_ok && state_.sensors.pose.valid) {
    state_.command.drive = mission_.update(state_.sensors.pose.pose);
  } else {
    state_.command.drive = {state_.command.drive.curvature, 0.0};
  }
}

void ActuateTask::run(const executive::TaskContext& /*ctx*/) noexcept { actuators_.write(state_.command); }

void TelemetryTask::run(const executive::TaskContext& ctx) noexcept {
  const auto& pose = state_.sensors.pose.pose;
  if (state_.sensors.pose.valid && ctx.frame % every_ == 0) telemetry_.record_pose(pose);
  if (state_.sensors.collided && !was_colliding_) telemetry_.record_collision(pose);
  was_colliding_ = state_.sensors.collided;
  telemetry_.record_goal(mission_.goals_reached(), state_.sensors.stamp);
  if (mission_.complete()) {
    telemetry_.record_pose(pose);  // end the trajectory where the mission ended
    ctx.request_stop();
  }
}

}  // namespace ringlet::firmware
