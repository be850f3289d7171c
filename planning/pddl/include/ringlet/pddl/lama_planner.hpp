#pragma once
// A LAMA-class forward planner (Richter & Westphal 2010, without landmarks): greedy best-first
// search with h_FF and deferred evaluation over two open lists, all successors and those
// reached by preferred operators, the preferred list boosted by 1000 turns whenever h improves;
// once a plan is found, weighted A* restarts from scratch with falling weights (5, 3, 2, 1 by
// default), each pruning what cannot beat the best plan so far, which is kept. step() slices
// every phase; a unit is one node taken from an open list.
#include <array>
#include <vector>

#include "ringlet/pddl/ff_heuristic.hpp"
#include "ringlet/pddl/open_list.hpp"
#include "ringlet/pddl/planner.hpp"
#include "ringlet/pddl/state_table.hpp"

namespace ringlet::pddl {

struct LamaOptions {
  std::array<std::int32_t, 4> weights{5, 3, 2, 1};  ///< the restarts after the first plan
  std::int32_t restarts = 4;                        ///< how many of `weights` to run (0: first plan only)
  std::int32_t preferred_boost = 1000;
};

class LamaPlanner final : public Planner {
 public:
  explicit LamaPlanner(const PlannerLimits& limits, LamaOptions options = {});

  [[nodiscard]] const char* name() const noexcept override { return "lama"; }
  PlannerStatus start(const Task& task, std::int32_t depth, ConstState from = {}) noexcept override;
  PlannerStatus step(std::uint32_t units) noexcept override;

  /// -1 while greedy best-first search runs, then the index of the weighted A* restart.
  [[nodiscard]] std::int32_t phase() const noexcept { return phase_; }

 private:
  enum class Next { kContinue, kPhaseDone, kFull };
  void begin_phase() noexcept;
  Next expand_one() noexcept;
  [[nodiscard]] std::int64_t key(std::int32_t g, std::int32_t parent_h) const noexcept;
  void keep_plan(std::int32_t goal_node) noexcept;
  PlannerStatus finish() noexcept;

  PlannerLimits limits_;
  LamaOptions options_;
  StateTable table_;
  OpenList all_, preferred_;
  FfHeuristic ff_;
  std::vector<std::int32_t> parent_, op_, g_, h_, closed_g_;
  std::vector<std::int32_t> best_plan_, path_;
  std::vector<std::uint64_t> start_state_, child_;
  const Task* task_ = nullptr;
  std::int32_t horizon_ = kNoHorizon;
  std::int32_t phase_ = -1;
  std::int32_t best_cost_ = 0;  // valid once stats_.plans_found > 0
  std::int32_t best_h_ = 0;     // the lowest h seen in this phase (for the boost)
  std::array<std::int32_t, 2> priority_{0, 0};  // all, preferred
};

}  // namespace ringlet::pddl
