#include "ringlet/firmware/tasks/actuate_task.hpp"

namespace ringlet::firmware {

std::unique_ptr<executive::Task> ActuateTask::make(TaskServices& services) {
  return std::make_unique<ActuateTask>(services.robot.actuators(), services.board);
}

void ActuateTask::run(const executive::TaskContext& /*ctx*/) noexcept {
  const auto motion = board_.get<wb::MotionCommand>();
  const auto head = board_.get<wb::HeadCommand>();
  hal::ActuatorCommand cmd;
  cmd.drive = {motion.curvature, motion.stop ? 0.0 : motion.velocity};
  cmd.head = {head.yaw, head.pitch};
  actuators_.write(cmd);
}

}  // namespace ringlet::firmware
