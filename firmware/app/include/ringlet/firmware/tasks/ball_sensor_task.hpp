#pragma once
// The backend's own ball detector → whiteboard BallBelief, marked `simulated` (the simulator's
// detector reports the true ball). For robots without a camera in the loop; with one, the vision
// task provides BallBelief instead (run one of the two).
#include <memory>

#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"
#include "ringlet/hal/ball_sensor.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

class BallSensorTask final : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{"ball_sensor", kNoTypes, kTypeNames<wb::BallBelief>,
                                                here()};
  static constexpr hal::Nanos kModelledCost{2'000};

  /// ConfigError when the robot has no ball sensor of its own.
  static std::unique_ptr<executive::Task> make(TaskServices& services);
  BallSensorTask(hal::BallSensor& sensor, wb::Whiteboard& board) noexcept : sensor_(sensor), board_(board) {}
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] hal::Nanos modelled_cost() const noexcept override { return kModelledCost; }

 private:
  hal::BallSensor& sensor_;
  wb::Whiteboard& board_;
};

}  // namespace ringlet::firmware
