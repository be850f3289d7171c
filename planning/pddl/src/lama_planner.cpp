#include "ringlet/pddl/lama_planner.hpp"

#include <algorithm>
#include <limits>

namespace ringlet::pddl {
namespace {
std::size_t ix(std::int32_t i) { return static_cast<std::size_t>(i); }
constexpr std::int32_t kUnknown = -2;  // h not evaluated yet
}  // namespace

LamaPlanner::LamaPlanner(const PlannerLimits& limits, LamaOptions options)
    : limits_(limits),
      options_(options),
      table_(limits.max_nodes, ix((limits.max_facts + 63) / 64)),
      all_(2 * limits.max_nodes),
      preferred_(2 * limits.max_nodes),
      ff_(limits),
      parent_(limits.max_nodes),
      op_(limits.max_nodes),
      g_(limits.max_nodes),
      h_(limits.max_nodes),
      closed_g_(limits.max_nodes),
      best_plan_(limits.max_nodes),
      path_(limits.max_nodes),
      start_state_(ix((limits.max_facts + 63) / 64)),
      child_(ix((limits.max_facts + 63) / 64)) {
  options_.restarts = std::clamp(options_.restarts, 0, static_cast<std::int32_t>(options_.weights.size()));
}

PlannerStatus LamaPlanner::start(const Task& task, std::int32_t depth, ConstState from) noexcept {
  begin(PlannerStatus::kRunning);
  task_ = &task;
  horizon_ = depth;
  phase_ = -1;
  best_cost_ = 0;
  if (task.fact_count > limits_.max_facts || static_cast<std::int64_t>(task.operators.size()) > limits_.max_operators ||
      static_cast<std::int64_t>(task.relaxed.size()) > limits_.max_relaxed) {
    set_reason("the task (%d facts, %zu operators, %zu relaxed actions) exceeds the planner's limits (%d, %d, %d)",
               task.fact_count, task.operators.size(), task.relaxed.size(), limits_.max_facts,
               limits_.max_operators, limits_.max_relaxed);
    status_ = PlannerStatus::kFailed;
    return status_;
  }
  const ConstState s = from.empty() ? task.initial : from;
  std::copy(s.begin(), s.begin() + task.words, start_state_.begin());
  begin_phase();
  return status_;
}

void LamaPlanner::begin_phase() noexcept {
  table_.clear(ix(task_->words));
  all_.clear();
  preferred_.clear();
  priority_ = {0, 0};
  best_h_ = std::numeric_limits<std::int32_t>::max();
  const auto r = table_.insert(std::span<const std::uint64_t>(start_state_).first(ix(task_->words)));
  if (r.index == StateTable::kFull) return;  // capacity 0: the next step reports it
  parent_[0] = -1;
  op_[0] = -1;
  g_[0] = 0;
  h_[0] = kUnknown;
  closed_g_[0] = std::numeric_limits<std::int32_t>::max();
  (void)all_.push(0, 0, 0);
}

std::int64_t LamaPlanner::key(std::int32_t g, std::int32_t parent_h) const noexcept {
  if (phase_ < 0) return parent_h;  // greedy: h alone
  return g + static_cast<std::int64_t>(options_.weights[ix(phase_)]) * parent_h;
}

void LamaPlanner::keep_plan(std::int32_t goal_node) noexcept {
  std::int32_t length = 0;
  for (std::int32_t k = goal_node; op_[ix(k)] >= 0; k = parent_[ix(k)]) path_[ix(length++)] = op_[ix(k)];
  std::reverse_copy(path_.begin(), path_.begin() + length, best_plan_.begin());
  best_cost_ = length;
  plan_ = std::span<const std::int32_t>(best_plan_).first(ix(length));
  if (stats_.plans_found++ == 0) stats_.first_plan_expansions = stats_.expansions;
  stats_.plan_length = length;
  stats_.plan_cost = length;
}

PlannerStatus LamaPlanner::finish() noexcept {
  if (stats_.plans_found > 0) {
    status_ = PlannerStatus::kFound;
  } else {
    status_ = PlannerStatus::kExhausted;
    if (horizon_ == kNoHorizon) {
      set_reason("no plan: every reachable state was expanded");
    } else {
      set_reason("no plan within the horizon of %d actions", horizon_);
    }
  }
  return status_;
}

LamaPlanner::Next LamaPlanner::expand_one() noexcept {
  const Task& t = *task_;
  // Alternate between the lists by priority; the preferred list wins ties.
  OpenList* list = nullptr;
  std::size_t which = 0;
  if (!preferred_.empty() && (all_.empty() || priority_[1] >= priority_[0])) {
    list = &preferred_;
    which = 1;
  } else if (!all_.empty()) {
    list = &all_;
  } else {
    return Next::kPhaseDone;
  }
  --priority_[which];
  const OpenEntry e = list->pop();
  const std::int32_t n = e.node;
  if (e.g != g_[ix(n)] || closed_g_[ix(n)] <= e.g) return Next::kContinue;  // stale or done
  closed_g_[ix(n)] = e.g;
  const std::int32_t g = g_[ix(n)];
  if (stats_.plans_found > 0 && g >= best_cost_) return Next::kContinue;  // cannot beat the plan kept
  ++stats_.expansions;
  const ConstState state = table_.state(n);
  if (goal_holds(t, state)) {
    keep_plan(n);
    return Next::kPhaseDone;
  }
  if (horizon_ != kNoHorizon && g >= horizon_) return Next::kContinue;
  // Deferred evaluation: h of the node being expanded, its successors queued with it.
  if (h_[ix(n)] == kUnknown) {
    h_[ix(n)] = ff_.evaluate(t, state);
    ++stats_.evaluations;
  } else {
    (void)ff_.evaluate(t, state);  // the preferred operators are needed again (re-expansion)
  }
  const std::int32_t h = h_[ix(n)];
  if (h == FfHeuristic::kInfinite) return Next::kContinue;  // a dead end
  if (h < best_h_) {
    if (best_h_ != std::numeric_limits<std::int32_t>::max()) priority_[1] += options_.preferred_boost;
    best_h_ = h;
  }
  const State child(child_.data(), ix(t.words));
  for (std::int32_t op = 0; op < static_cast<std::int32_t>(t.operators.size()); ++op) {
    if (!applicable(t, op, state)) continue;
    const std::int32_t cg = g + 1;
    if (stats_.plans_found > 0 && cg >= best_cost_) continue;
    apply(t, op, state, child);
    ++stats_.generated;
    const auto r = table_.insert(child);
    if (r.index == StateTable::kFull) return Next::kFull;
    const auto c = ix(r.index);
    if (r.inserted) {
      h_[c] = kUnknown;
      closed_g_[c] = std::numeric_limits<std::int32_t>::max();
    } else if ((phase_ < 0 && horizon_ == kNoHorizon) || cg >= g_[c]) {
      // Greedy search never reopens; weighted A* only for a cheaper path, and so does greedy
      // search under a horizon (else a state first reached too deep would hide a plan).
      continue;
    }
    parent_[c] = n;
    op_[c] = op;
    g_[c] = cg;
    const std::int64_t k = key(cg, h);
    if (!all_.push(k, r.index, cg)) return Next::kFull;
    if (ff_.is_preferred(op) && !preferred_.push(k, r.index, cg)) return Next::kFull;
  }
  return Next::kContinue;
}

PlannerStatus LamaPlanner::step(std::uint32_t units) noexcept {
  if (status_ != PlannerStatus::kRunning) return status_;
  std::uint32_t used = 0;
  while (used < units && status_ == PlannerStatus::kRunning) {
    ++used;
    switch (expand_one()) {
      case Next::kContinue: break;
      case Next::kFull:
        if (stats_.plans_found > 0) {
          set_reason("stopped improving: node capacity (%zu) reached in restart %d", table_.capacity(), phase_);
          status_ = PlannerStatus::kFound;
        } else {
          set_reason("node capacity (%zu states) exhausted before a plan was found", table_.capacity());
          status_ = PlannerStatus::kFailed;
        }
        break;
      case Next::kPhaseDone:
        // Greedy search without a plan has searched everything: no weighted A* can do better.
        if (stats_.plans_found == 0 || phase_ + 1 >= options_.restarts) {
          finish();
        } else {
          ++phase_;
          begin_phase();
        }
        break;
    }
  }
  count_slice(used);
  return status_;
}

}  // namespace ringlet::pddl
