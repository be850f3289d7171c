#pragma once
// Records the planner's work for the report and the picture (an observer: it reads Plan and
// writes only the run's record): every cell the planner marked occupied (Plan.new_cells), the
// first plan to each goal and every plan after a replan. It reads every Plan generation posted
// since its last activation, so none is lost while the ring holds it.
#include <memory>

#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"
#include "ringlet/firmware/telemetry.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

class PlanRecordTask final : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{"plan_record", kTypeNames<wb::Plan>, kNoTypes, here()};
  static constexpr hal::Nanos kModelledCost{5'000};
  /// Plans kept for the picture (the first to each goal, every replan's).
  static constexpr std::size_t kMaxPlans = 4096;

  static std::unique_ptr<executive::Task> make(TaskServices& services);
  PlanRecordTask(Telemetry& telemetry, const wb::Whiteboard& board) noexcept : telemetry_(telemetry), board_(board) {}
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] hal::Nanos modelled_cost() const noexcept override { return kModelledCost; }

 private:
  void record(const wb::Plan& plan) noexcept;

  Telemetry& telemetry_;
  const wb::Whiteboard& board_;
  std::uint64_t seen_ = 0;  // the last Plan generation read
  bool have_last_ = false;
  double last_goal_x_ = 0.0, last_goal_y_ = 0.0;
  std::uint32_t last_replans_ = 0;
  std::array<hal::WorldPoint, 64> path_{};
};

}  // namespace ringlet::firmware
