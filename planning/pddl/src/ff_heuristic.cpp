#include "ringlet/pddl/ff_heuristic.hpp"

#include <algorithm>

namespace ringlet::pddl {
namespace {
std::size_t ix(std::int32_t i) { return static_cast<std::size_t>(i); }
}  // namespace

FfHeuristic::FfHeuristic(const PlannerLimits& l)
    : level_(ix(l.max_facts)),
      supporter_(ix(l.max_facts)),
      level_epoch_(ix(l.max_facts)),
      marked_epoch_(ix(l.max_facts)),
      queue_(ix(l.max_facts)),
      unmet_(ix(l.max_relaxed)),
      unmet_epoch_(ix(l.max_relaxed)),
      in_plan_epoch_(ix(l.max_operators)),
      preferred_epoch_(ix(l.max_operators)),
      preferred_(ix(l.max_operators)) {}

std::int32_t FfHeuristic::evaluate(const Task& t, ConstState state) noexcept {
  if (++epoch_ == 0) {  // wrapped: old marks could look current, wipe them once
    for (auto* v : {&level_epoch_, &marked_epoch_, &unmet_epoch_, &in_plan_epoch_, &preferred_epoch_}) {
      std::fill(v->begin(), v->end(), 0U);
    }
    epoch_ = 1;
  }
  preferred_count_ = 0;
  std::size_t head = 0;
  std::size_t tail = 0;
  auto reach = [&](std::int32_t f, std::int32_t level, std::int32_t supporter) {
    if (level_epoch_[ix(f)] == epoch_) return;
    level_epoch_[ix(f)] = epoch_;
    level_[ix(f)] = level;
    supporter_[ix(f)] = supporter;
    queue_[tail++] = f;
  };
  for (std::int32_t f = 0; f < t.fact_count; ++f) {
    if (is_set(state, f)) reach(f, 0, -1);
  }
  // Relaxed actions without conditions fire at once.
  for (std::size_t r = 0; r < t.relaxed.size(); ++r) {
    if (t.relaxed[r].pre.count == 0) {
      for (const std::int32_t f : t.list(t.relaxed[r].add)) reach(f, 1, static_cast<std::int32_t>(r));
    }
  }
  const auto goals = t.list(t.goal_pos);
  auto all_goals_reached = [&] {
    return std::all_of(goals.begin(), goals.end(), [&](std::int32_t g) { return level_epoch_[ix(g)] == epoch_; });
  };
  // Breadth-first over facts: a relaxed action fires when its last condition is reached, one
  // level after it; facts leave the queue in order of level.
  while (head < tail && !all_goals_reached()) {
    const std::int32_t f = queue_[head++];
    const Range users = t.relaxed_by_pre[ix(f)];
    for (const std::int32_t r : t.list(users)) {
      if (unmet_epoch_[ix(r)] != epoch_) {
        unmet_epoch_[ix(r)] = epoch_;
        unmet_[ix(r)] = static_cast<std::int32_t>(t.relaxed[ix(r)].pre.count);
      }
      if (--unmet_[ix(r)] == 0) {
        for (const std::int32_t a : t.list(t.relaxed[ix(r)].add)) reach(a, level_[ix(f)] + 1, r);
      }
    }
  }
  if (!all_goals_reached()) return kInfinite;
  // Relaxed plan: the goals' supporters, then their conditions' supporters (the queue's array
  // is free again and holds the agenda).
  std::int32_t h = 0;
  std::size_t agenda = 0;
  for (const std::int32_t g : goals) {
    if (marked_epoch_[ix(g)] != epoch_) {
      marked_epoch_[ix(g)] = epoch_;
      queue_[agenda++] = g;
    }
  }
  while (agenda > 0) {
    const std::int32_t f = queue_[--agenda];
    const std::int32_t r = supporter_[ix(f)];
    if (r < 0) continue;  // true in the state
    const RelaxedAction& ra = t.relaxed[ix(r)];
    if (in_plan_epoch_[ix(ra.op)] != epoch_) {
      in_plan_epoch_[ix(ra.op)] = epoch_;
      ++h;
      if (applicable(t, ra.op, state)) {
        preferred_epoch_[ix(ra.op)] = epoch_;
        preferred_[preferred_count_++] = ra.op;
      }
    }
    for (const std::int32_t p : t.list(ra.pre)) {
      if (marked_epoch_[ix(p)] != epoch_) {
        marked_epoch_[ix(p)] = epoch_;
        queue_[agenda++] = p;
      }
    }
  }
  std::sort(preferred_.begin(), preferred_.begin() + static_cast<std::ptrdiff_t>(preferred_count_));
  for (const std::int32_t g : t.list(t.goal_neg)) {
    if (is_set(state, g)) ++h;
  }
  return h;
}

}  // namespace ringlet::pddl
