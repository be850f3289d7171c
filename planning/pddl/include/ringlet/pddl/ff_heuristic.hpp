#pragma once
// h_FF (Hoffmann & Nebel 2001): the length of a relaxed plan (deletes ignored) extracted from
// the relaxed planning graph, with its preferred operators (FF's helpful actions: relaxed-plan
// operators applicable in the state). Arrays sized at construction; evaluate() never
// allocates. Negative conditions are ignored by the relaxation; each negative goal still false
// adds 1 so that h is 0 exactly in goal states.
#include <cstdint>
#include <span>
#include <vector>

#include "ringlet/pddl/planner.hpp"
#include "ringlet/pddl/task.hpp"

namespace ringlet::pddl {

class FfHeuristic {
 public:
  static constexpr std::int32_t kInfinite = -1;

  explicit FfHeuristic(const PlannerLimits& limits);

  /// h_FF of `state` (kInfinite: the goal is unreachable even relaxed); preferred() then holds
  /// the preferred operators in increasing order of index.
  [[nodiscard]] std::int32_t evaluate(const Task& task, ConstState state) noexcept;
  [[nodiscard]] std::span<const std::int32_t> preferred() const noexcept {
    return std::span<const std::int32_t>(preferred_).first(preferred_count_);
  }
  /// Whether `op` is among preferred() (O(1)).
  [[nodiscard]] bool is_preferred(std::int32_t op) const noexcept {
    return preferred_epoch_[static_cast<std::size_t>(op)] == epoch_;
  }

 private:
  std::uint32_t epoch_ = 0;
  std::vector<std::int32_t> level_;            // per fact, valid when level_epoch_ is current
  std::vector<std::int32_t> supporter_;        // per fact: the relaxed action that reached it first
  std::vector<std::uint32_t> level_epoch_;
  std::vector<std::uint32_t> marked_epoch_;    // per fact: already in the relaxed plan's agenda
  std::vector<std::int32_t> queue_;            // facts in order of level
  std::vector<std::int32_t> unmet_;            // per relaxed action: conditions not reached yet
  std::vector<std::uint32_t> unmet_epoch_;
  std::vector<std::uint32_t> in_plan_epoch_;   // per operator
  std::vector<std::uint32_t> preferred_epoch_; // per operator
  std::vector<std::int32_t> preferred_;
  std::size_t preferred_count_ = 0;
};

}  // namespace ringlet::pddl
