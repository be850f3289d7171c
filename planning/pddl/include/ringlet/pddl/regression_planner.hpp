#pragma once
// Mi-Pal's regression planner: breadth-first search backwards from the goal. A node is a
// subgoal, a pair of fact sets (must be true, must be false); regressing it through an
// operator that achieves part of it and destroys none of it gives the subgoal that must hold
// before the operator. The first subgoal the start state satisfies ends the search, and
// breadth-first order makes that plan as short as any (unit costs). The depth is the horizon:
// subgoals deeper than it are not regressed further. Conditional effects are refused (their
// regression is a disjunction); the LAMA-class planner handles them.
#include <vector>

#include "ringlet/pddl/planner.hpp"
#include "ringlet/pddl/state_table.hpp"

namespace ringlet::pddl {

class RegressionPlanner final : public Planner {
 public:
  explicit RegressionPlanner(const PlannerLimits& limits);

  [[nodiscard]] const char* name() const noexcept override { return "regression"; }
  PlannerStatus start(const Task& task, std::int32_t depth, ConstState from = {}) noexcept override;
  PlannerStatus step(std::uint32_t units) noexcept override;

 private:
  /// Regresses node `n` through every relevant operator; false when the table is full.
  bool expand(std::int32_t n) noexcept;
  [[nodiscard]] bool satisfied_by_start(std::int32_t n) const noexcept;
  void extract(std::int32_t n) noexcept;
  PlannerStatus fail(const char* why) noexcept;

  PlannerLimits limits_;
  StateTable table_;
  std::vector<std::int32_t> parent_, op_, depth_;
  std::vector<std::uint64_t> start_state_, scratch_;
  std::vector<std::int32_t> plan_buffer_;
  const Task* task_ = nullptr;
  std::int32_t horizon_ = kNoHorizon;
  std::int32_t next_ = 0;  // breadth-first: nodes are expanded in the order they were stored
};

}  // namespace ringlet::pddl
