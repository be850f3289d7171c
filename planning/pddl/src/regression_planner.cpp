#include "ringlet/pddl/regression_planner.hpp"

#include <algorithm>

namespace ringlet::pddl {
namespace {
std::size_t ix(std::int32_t i) { return static_cast<std::size_t>(i); }
}  // namespace

RegressionPlanner::RegressionPlanner(const PlannerLimits& limits)
    : limits_(limits),
      table_(limits.max_nodes, 2 * ix((limits.max_facts + 63) / 64)),
      parent_(limits.max_nodes),
      op_(limits.max_nodes),
      depth_(limits.max_nodes),
      start_state_(ix((limits.max_facts + 63) / 64)),
      scratch_(2 * ix((limits.max_facts + 63) / 64)),
      plan_buffer_(limits.max_nodes) {}

PlannerStatus RegressionPlanner::fail(const char* why) noexcept {
  set_reason("%s", why);
  status_ = PlannerStatus::kFailed;
  return status_;
}

PlannerStatus RegressionPlanner::start(const Task& task, std::int32_t depth, ConstState from) noexcept {
  begin(PlannerStatus::kRunning);
  task_ = &task;
  horizon_ = depth;
  next_ = 0;
  if (task.fact_count > limits_.max_facts) return fail("the task has more facts than the planner's max_facts");
  if (task.has_conditional_effects) {
    return fail("the regression planner does not handle conditional effects: use the lama planner");
  }
  const auto words = ix(task.words);
  const ConstState s = from.empty() ? task.initial : from;
  std::copy(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(words), start_state_.begin());
  if (task.goal_false) {
    set_reason("the goal holds an equality between different objects");
    status_ = PlannerStatus::kExhausted;
    return status_;
  }
  // The root: the goal as a subgoal (positive facts in the first half, negative in the second).
  table_.clear(2 * words);
  const State root(scratch_.data(), 2 * words);
  std::fill(root.begin(), root.end(), 0U);
  for (const std::int32_t f : task.list(task.goal_pos)) set(root.first(words), f);
  for (const std::int32_t f : task.list(task.goal_neg)) set(root.subspan(words), f);
  const auto r = table_.insert(root);
  if (r.index == StateTable::kFull) return fail("node capacity is zero");
  parent_[0] = -1;
  op_[0] = -1;
  depth_[0] = 0;
  return status_;
}

bool RegressionPlanner::satisfied_by_start(std::int32_t n) const noexcept {
  const auto words = ix(task_->words);
  const ConstState sub = table_.state(n);
  for (std::size_t w = 0; w < words; ++w) {
    if ((sub[w] & ~start_state_[w]) != 0 || (sub[words + w] & start_state_[w]) != 0) return false;
  }
  return true;
}

bool RegressionPlanner::expand(std::int32_t n) noexcept {
  const Task& t = *task_;
  const auto words = ix(t.words);
  ++stats_.expansions;
  for (std::int32_t op = 0; op < static_cast<std::int32_t>(t.operators.size()); ++op) {
    const ConstState sub = table_.state(n);
    const ConstState pos = sub.first(words);
    const ConstState neg = sub.subspan(words);
    const GroundOperator& o = t.operators[ix(op)];
    const auto add = t.list(o.add);
    const auto del = t.list(o.del);
    // Relevant: achieves part of the subgoal. Consistent: destroys none of it.
    const bool relevant = std::any_of(add.begin(), add.end(), [&](std::int32_t f) { return is_set(pos, f); }) ||
                          std::any_of(del.begin(), del.end(), [&](std::int32_t f) { return is_set(neg, f); });
    if (!relevant || !none_true(pos, del) || !none_true(neg, add)) continue;
    const State next(scratch_.data(), 2 * words);
    std::copy(sub.begin(), sub.end(), next.begin());
    for (const std::int32_t f : add) clear(next.first(words), f);
    for (const std::int32_t f : del) clear(next.subspan(words), f);
    for (const std::int32_t f : t.list(o.pre_pos)) set(next.first(words), f);
    for (const std::int32_t f : t.list(o.pre_neg)) set(next.subspan(words), f);
    bool contradiction = false;
    for (std::size_t w = 0; w < words; ++w) contradiction = contradiction || (next[w] & next[words + w]) != 0;
    if (contradiction) continue;
    ++stats_.generated;
    const auto r = table_.insert(next);
    if (r.index == StateTable::kFull) return false;
    if (!r.inserted) continue;
    parent_[ix(r.index)] = n;
    op_[ix(r.index)] = op;
    depth_[ix(r.index)] = depth_[ix(n)] + 1;
  }
  return true;
}

void RegressionPlanner::extract(std::int32_t n) noexcept {
  // The chain from the satisfied subgoal up to the goal lists the actions first to last.
  std::size_t length = 0;
  for (std::int32_t k = n; op_[ix(k)] >= 0; k = parent_[ix(k)]) plan_buffer_[length++] = op_[ix(k)];
  plan_ = std::span<const std::int32_t>(plan_buffer_).first(length);
  stats_.plans_found = 1;
  stats_.first_plan_expansions = stats_.expansions;
  stats_.plan_length = static_cast<std::int32_t>(length);
  stats_.plan_cost = stats_.plan_length;
}

PlannerStatus RegressionPlanner::step(std::uint32_t units) noexcept {
  if (status_ != PlannerStatus::kRunning) return status_;
  std::uint32_t used = 0;
  while (used < units) {
    if (ix(next_) == table_.size()) {
      set_reason(horizon_ == kNoHorizon ? "no plan: every subgoal was regressed"
                                        : "no plan within the horizon of %d actions", horizon_);
      status_ = PlannerStatus::kExhausted;
      break;
    }
    const std::int32_t n = next_++;
    ++used;
    if (satisfied_by_start(n)) {
      extract(n);
      status_ = PlannerStatus::kFound;
      break;
    }
    if (horizon_ != kNoHorizon && depth_[ix(n)] >= horizon_) continue;
    if (!expand(n)) {
      set_reason("node capacity (%zu subgoals) exhausted before a plan was found", table_.capacity());
      status_ = PlannerStatus::kFailed;
      break;
    }
  }
  count_slice(used);
  return status_;
}

}  // namespace ringlet::pddl
