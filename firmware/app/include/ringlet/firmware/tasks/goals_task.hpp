#pragma once
// The mission's goals from the configuration ([mission] goals) → whiteboard MissionGoals, posted
// at every activation so that a monitor joining late sees them too. The Mission machine reads them.
#include <memory>

#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

class GoalsTask final : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{"goals", kNoTypes, kTypeNames<wb::MissionGoals>,
                                                here()};
  static constexpr hal::Nanos kModelledCost{2'000};

  static std::unique_ptr<executive::Task> make(TaskServices& services);
  GoalsTask(const wb::MissionGoals& goals, wb::Whiteboard& board) noexcept : goals_(goals), board_(board) {}
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] hal::Nanos modelled_cost() const noexcept override { return kModelledCost; }

 private:
  wb::MissionGoals goals_;
  wb::Whiteboard& board_;
};

}  // namespace ringlet::firmware
