#pragma once
// Whiteboard MotionCommand and HeadCommand → HAL actuators. `stop` means v = 0. HeadCommand is
// optional: a robot without ball tracking ([mission] ball_tracking = false) has no machine that
// points the head, which then holds straight ahead (the default HeadCommand).
#include <memory>

#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"
#include "ringlet/hal/actuators.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

class ActuateTask final : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{"actuate", kTypeNames<wb::MotionCommand>, kNoTypes, here(),
                                                kTypeNames<wb::HeadCommand>};
  static constexpr hal::Nanos kModelledCost{3'000};

  static std::unique_ptr<executive::Task> make(TaskServices& services);
  ActuateTask(hal::Actuators& actuators, const wb::Whiteboard& board) noexcept : actuators_(actuators), board_(board) {}
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] hal::Nanos modelled_cost() const noexcept override { return kModelledCost; }

 private:
  hal::Actuators& actuators_;
  const wb::Whiteboard& board_;
};

}  // namespace ringlet::firmware
