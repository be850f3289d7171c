#include "ringlet/firmware/tasks/ball_sensor_task.hpp"

namespace ringlet::firmware {

std::unique_ptr<executive::Task> BallSensorTask::make(TaskServices& services) {
  hal::BallSensor* sensor = services.robot.ball_sensor();
  if (sensor == nullptr) {
    throw ConfigError(services.config.positions.at("executive.tasks") + ": task 'ball_sensor': the " +
                      std::string(services.robot.backend_name()) +
                      " backend has no ball detector of its own; run the vision task instead");
  }
  return std::make_unique<BallSensorTask>(*sensor, services.board);
}

void BallSensorTask::run(const executive::TaskContext& /*ctx*/) noexcept {
  hal::BallSighting sighting;
  wb::BallBelief ball{};
  if (sensor_.read(sighting) && sighting.seen) {
    ball.visible = true;
    ball.x = sighting.at.x;
    ball.y = sighting.at.y;
    ball.confidence = 1.0;
  }
  ball.simulated = true;  // the backend's detector, not the controller's vision
  board_.post(ball);
}

}  // namespace ringlet::firmware
