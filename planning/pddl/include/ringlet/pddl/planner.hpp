#pragma once
// One interface for the planners the service loads (LOAD_PLANNER): start() a search on a
// grounded task with an optional horizon (START_PLANNER(depth), RE-PLAN(source, depth)), then
// step() it in slices of work units from the cycle. Every array a planner uses is allocated in
// its constructor from PlannerLimits; start() and step() never allocate, block or loop beyond
// the budget they are given. Running out of a configured capacity is a status with a reason.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "ringlet/pddl/task.hpp"

namespace ringlet::pddl {

enum class PlannerStatus {
  kIdle,       ///< not started
  kRunning,    ///< call step() again
  kFound,      ///< finished with a plan (plan())
  kFailed,     ///< could not finish: a capacity ran out, or the task is beyond this planner (reason())
  kExhausted,  ///< the whole search space (within the horizon) was searched: no plan exists
};

[[nodiscard]] const char* to_string(PlannerStatus s) noexcept;

/// Sizes fixed at construction (start-up). A task larger than these is refused by start().
struct PlannerLimits {
  std::size_t max_nodes = 200000;    ///< search nodes (states or subgoals) stored at once
  std::int32_t max_facts = 4096;
  std::int32_t max_operators = 65536;
  std::int32_t max_relaxed = 65536;  ///< relaxed actions (operators plus conditional effects)

  /// Limits that fit `task` exactly, with `nodes` search nodes (for tools and tests).
  [[nodiscard]] static PlannerLimits for_task(const Task& task, std::size_t nodes);
};

struct PlannerStats {
  std::uint64_t expansions = 0;   ///< nodes expanded (the work unit of step())
  std::uint64_t generated = 0;    ///< successors (or regressions) generated
  std::uint64_t evaluations = 0;  ///< heuristic evaluations
  std::uint64_t slices = 0;       ///< step() calls
  std::uint32_t max_units_in_slice = 0;
  std::int32_t plans_found = 0;   ///< LAMA: first plan plus every improvement
  std::uint64_t first_plan_expansions = 0;  ///< expansions when the first plan was found
  std::int32_t plan_length = 0;
  std::int32_t plan_cost = 0;     ///< unit costs: the length
};

constexpr std::int32_t kNoHorizon = -1;

class Planner {
 public:
  Planner() = default;
  Planner(const Planner&) = delete;
  Planner& operator=(const Planner&) = delete;
  virtual ~Planner() = default;

  [[nodiscard]] virtual const char* name() const noexcept = 0;

  /// Begins a search for a plan of at most `depth` actions (kNoHorizon: any length) from
  /// `from` (empty: the task's initial state). The task must outlive the search.
  virtual PlannerStatus start(const Task& task, std::int32_t depth, ConstState from = {}) noexcept = 0;
  /// Works for at most `units` expansions and returns where the search stands.
  virtual PlannerStatus step(std::uint32_t units) noexcept = 0;

  [[nodiscard]] PlannerStatus status() const noexcept { return status_; }
  /// The plan as operator indices, first action first (empty unless kFound).
  [[nodiscard]] std::span<const std::int32_t> plan() const noexcept { return plan_; }
  [[nodiscard]] const PlannerStats& stats() const noexcept { return stats_; }
  /// Why the search failed or stopped early ("" otherwise).
  [[nodiscard]] const char* reason() const noexcept { return reason_.data(); }

 protected:
  /// Formats the reason into a fixed buffer (no allocation).
  void set_reason(const char* format, ...) noexcept __attribute__((format(printf, 2, 3)));
  void begin(PlannerStatus s) noexcept;
  /// Counts a slice of `units` work units.
  void count_slice(std::uint32_t units) noexcept;

  PlannerStatus status_ = PlannerStatus::kIdle;
  std::span<const std::int32_t> plan_;
  PlannerStats stats_;

 private:
  std::array<char, 200> reason_{};
};

}  // namespace ringlet::pddl
