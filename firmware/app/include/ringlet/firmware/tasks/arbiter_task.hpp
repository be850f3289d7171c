#pragma once
// The reactive layer in the cycle (Powers & Balch §III-A): from the newest laser scan, the pose
// and the plan's waypoint, the five behaviours vote over the arcs and the arbiter picks one
// (behaviour/reactive). Posts ArbiterCommand: the decision and every behaviour's votes. It does not
// drive: the Navigate machine turns the decision into MotionCommand, and the Safety machine, which
// runs after it in the same turn, keeps the last word.
#include <memory>

#include "ringlet/behaviour/reactive/voting.hpp"
#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

class ArbiterTask final : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{"arbiter", kTypeNames<wb::Pose, wb::LaserScan, wb::Plan>,
                                                kTypeNames<wb::ArbiterCommand>, here()};
  /// The board's cost: a fixed part and one clearance test per (arc, nearby point) pair, twice
  /// (the obstacle space and the congestion space).
  static constexpr hal::Nanos kBaseCost{15'000};
  static constexpr hal::Nanos kCostPerTest{40};

  static std::unique_ptr<executive::Task> make(TaskServices& services);
  ArbiterTask(const behaviour::reactive::ReactiveParams& params, wb::Whiteboard& board) noexcept
      : params_(params), board_(board) {}
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] hal::Nanos modelled_cost() const noexcept override { return cost_; }

 private:
  behaviour::reactive::ReactiveParams params_;
  wb::Whiteboard& board_;
  behaviour::reactive::ObstaclePoints obstacles_{};
  behaviour::reactive::ReactiveStep step_{};
  wb::ArbiterCommand out_{};
  hal::Nanos cost_{kBaseCost};
};

}  // namespace ringlet::firmware
