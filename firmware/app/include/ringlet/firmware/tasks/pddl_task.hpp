#pragma once
// The PDDL planner service in the cycle (issue 15; Mi-Pal §5): the six operations of Mi-Pal's
// whiteboard API, LOAD_PLANNER, LOAD_PDDL, START_PLANNER(depth), NEXT_ACTION(rank),
// RE-PLAN(source, depth), IS_OBSTACLE_KNOWN(position), each a PddlRequest with an id answered by
// a PddlReply with that id, success or failure and a reason.
//
// Idempotent by id: a request is carried out once; its id again gets the same reply again (a
// reply may have been lost), a smaller id is stale and ignored, and while an operation runs the
// service takes no other (the requester repeats it). LOAD_PDDL and IS_OBSTACLE_KNOWN (which
// updates the problem and grounds it again) run on the service thread (pddl::ServiceWorker) into
// the back one of two arenas sized at start-up; the new task is taken over in the activation
// after the request (lockstep, waiting for the worker if it is late) or in the first one that
// finds it done (the real clock, never waiting). START_PLANNER and RE-PLAN step the chosen
// planner for [pddl] units_per_slice expansions per activation until it finishes: a
// deterministic amount of work. NEXT_ACTION(rank) answers with the action's number, name,
// arguments and the places' positions, and takes the actions before it as done: that is the
// believed state RE-PLAN starts from (its source atom put in) and IS_OBSTACLE_KNOWN writes into
// the problem. Requests and replies pass through a LossyLink each ([pddl] link_*: perfect by
// default), the model of a UDP link the lossy test uses. Nothing here allocates after start-up.
#include <cstdint>
#include <memory>
#include <vector>

#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/lossy_link.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"
#include "ringlet/pddl/lama_planner.hpp"
#include "ringlet/pddl/regression_planner.hpp"
#include "ringlet/pddl/service_worker.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

/// What the service did, for the report and the tests.
struct PddlServiceCounts {
  std::uint64_t requests = 0;      ///< delivered to the service
  std::uint64_t carried_out = 0;   ///< new ids
  std::uint64_t repeated = 0;      ///< an id again: its reply sent again
  std::uint64_t stale = 0;         ///< ids below the last one: ignored
  std::uint64_t busy = 0;          ///< another id while an operation ran: ignored
  std::uint64_t plans = 0;         ///< START_PLANNER / RE-PLAN that found a plan
  std::uint64_t obstacles_added = 0;
  std::uint32_t max_units = 0;     ///< the most expansions in one activation
};

class PddlTask final : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{"pddl", kTypeNames<wb::PddlRequest>, kTypeNames<wb::PddlReply>,
                                                here()};
  /// The board's cost: a fixed part, every request handled, every planner expansion (LAMA's
  /// mean of ~1.3 us per expansion on the desktop's small tasks, ringlet_bench_pddl, times an
  /// assumed board slowdown of 3), every action applied to the believed state.
  static constexpr hal::Nanos kBaseCost{5'000};
  static constexpr hal::Nanos kCostPerRequest{5'000};
  static constexpr hal::Nanos kCostPerUnit{4'000};
  static constexpr hal::Nanos kCostPerApplied{500};

  static std::unique_ptr<executive::Task> make(TaskServices& services);
  PddlTask(const PddlSettings& settings, wb::Whiteboard& board, bool realtime);
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] hal::Nanos modelled_cost() const noexcept override { return cost_; }

  [[nodiscard]] const PddlServiceCounts& counts() const noexcept { return counts_; }
  [[nodiscard]] const LossyLinkCounts& requests_link() const noexcept { return in_.counts(); }
  [[nodiscard]] const LossyLinkCounts& replies_link() const noexcept { return out_.counts(); }
  /// The task being planned on (null before the first LOAD_PDDL).
  [[nodiscard]] const pddl::Task* task() const noexcept { return task_; }

 private:
  enum class Busy : std::uint8_t { kNone, kWorker, kSearch };

  void handle(const wb::PddlRequest& r) noexcept;
  void begin(const wb::PddlRequest& r) noexcept;
  void start_search(std::int32_t depth) noexcept;
  void step_search() noexcept;
  void take_worker_result() noexcept;
  void next_action(const wb::PddlRequest& r) noexcept;
  void replan(const wb::PddlRequest& r) noexcept;
  /// The believed state: the plan's start with its first `done` actions applied.
  void advance_belief(std::int32_t done) noexcept;
  [[nodiscard]] wb::PddlReply reply_to(const wb::PddlRequest& r, bool ok) const noexcept;
  void send(const wb::PddlReply& reply) noexcept;
  void fail(const wb::PddlRequest& r, const char* format, ...) noexcept __attribute__((format(printf, 3, 4)));

  PddlSettings settings_;
  wb::Whiteboard& board_;
  bool realtime_;
  pddl::ServiceWorker worker_;
  pddl::RegressionPlanner regression_;
  pddl::LamaPlanner lama_;
  pddl::Planner* planner_ = nullptr;  // LOAD_PLANNER's choice
  pddl::Task task_storage_{};
  const pddl::Task* task_ = nullptr;
  std::vector<std::uint64_t> start_, belief_, scratch_;  // states, sized at start-up
  bool has_plan_ = false;
  std::uint32_t plan_number_ = 0;
  std::int32_t depth_ = 0;  // the running search's horizon, for its reply
  LossyLink<wb::PddlRequest> in_;
  LossyLink<wb::PddlReply> out_;
  std::uint64_t seen_generation_ = 0;
  std::uint64_t activation_ = 0;
  std::uint64_t submitted_at_ = 0;  // the activation that handed the worker its job
  std::uint32_t last_id_ = 0;
  Busy busy_ = Busy::kNone;
  wb::PddlRequest current_{};
  wb::PddlReply last_reply_{};
  bool replied_ = false;  // last_reply_ answers last_id_
  PddlServiceCounts counts_{};
  std::uint64_t requests_now_ = 0, applied_now_ = 0, units_now_ = 0;
  hal::Nanos cost_{kBaseCost};
};

}  // namespace ringlet::firmware
