#pragma once
// Records the PDDL service's plans for the picture (an observer: it reads PddlRequest and
// PddlReply and writes only the run's record). Each plan is drawn through the places its actions
// name, as the machine asked for them (NEXT_ACTION's reply carries each argument's position), one
// polyline per plan number, so the first plan and every re-plan after an obstacle show apart; and
// every IS_OBSTACLE_KNOWN position the machine reported. It reads every generation posted since
// its last activation; a repeated reply (a lost or repeated exchange) adds nothing.
#include <array>
#include <cstdint>
#include <memory>

#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"
#include "ringlet/firmware/telemetry.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

class PddlRecordTask final : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{"pddl_record", kTypeNames<wb::PddlRequest, wb::PddlReply>, kNoTypes,
                                                here()};
  static constexpr hal::Nanos kModelledCost{5'000};
  static constexpr std::size_t kMaxPlans = 256;
  static constexpr std::size_t kMaxPointsPerPlan = 64;
  static constexpr std::size_t kMaxReportedObstacles = 256;

  static std::unique_ptr<executive::Task> make(TaskServices& services);
  PddlRecordTask(Telemetry& telemetry, const wb::Whiteboard& board) noexcept : telemetry_(telemetry), board_(board) {}
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] hal::Nanos modelled_cost() const noexcept override { return kModelledCost; }

 private:
  void on_reply(const wb::PddlReply& reply) noexcept;
  void on_request(const wb::PddlRequest& request) noexcept;

  Telemetry& telemetry_;
  const wb::Whiteboard& board_;
  std::uint64_t replies_seen_ = 0;   // the last PddlReply generation read
  std::uint64_t requests_seen_ = 0;  // the last PddlRequest generation read
  std::uint32_t plan_ = 0;           // the plan being drawn (0: none yet)
  std::int32_t next_rank_ = 0;       // the rank that extends it
  std::uint32_t last_obstacle_id_ = 0;
  bool have_obstacle_id_ = false;
};

}  // namespace ringlet::firmware
