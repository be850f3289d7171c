#pragma once
// The LLFSM schedule: one turn of every machine per activation, on the executive's clock. What the
// machines require and provide is declared by the machines themselves (their footprints), so this
// task declares nothing of its own.
#include <memory>

#include "ringlet/behaviour/llfsm/schedule.hpp"
#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"

namespace ringlet::firmware {

class FsmTask final : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{"fsm", kNoTypes, kNoTypes, here()};
  /// A fixed part per turn (bus poll) and one per ringlet.
  static constexpr hal::Nanos kTurnCost{2'000};
  static constexpr hal::Nanos kRingletCost{1'000};

  static std::unique_ptr<executive::Task> make(TaskServices& services);
  explicit FsmTask(behaviour::llfsm::Schedule& schedule) noexcept : schedule_(schedule) {}
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] hal::Nanos modelled_cost() const noexcept override;

 private:
  behaviour::llfsm::Schedule& schedule_;
};

}  // namespace ringlet::firmware
