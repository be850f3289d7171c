#include "ringlet/pddl/planner.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

namespace ringlet::pddl {

const char* to_string(PlannerStatus s) noexcept {
  switch (s) {
    case PlannerStatus::kIdle: return "idle";
    case PlannerStatus::kRunning: return "running";
    case PlannerStatus::kFound: return "found";
    case PlannerStatus::kFailed: return "failed";
    case PlannerStatus::kExhausted: return "exhausted";
  }
  return "?";
}

PlannerLimits PlannerLimits::for_task(const Task& task, std::size_t nodes) {
  PlannerLimits l;
  l.max_nodes = nodes;
  l.max_facts = std::max(task.fact_count, 1);
  l.max_operators = std::max(static_cast<std::int32_t>(task.operators.size()), 1);
  l.max_relaxed = std::max(static_cast<std::int32_t>(task.relaxed.size()), 1);
  return l;
}

void Planner::set_reason(const char* format, ...) noexcept {
  va_list args;
  va_start(args, format);
  std::vsnprintf(reason_.data(), reason_.size(), format, args);
  va_end(args);
}

void Planner::begin(PlannerStatus s) noexcept {
  status_ = s;
  plan_ = {};
  stats_ = {};
  reason_[0] = '\0';
}

void Planner::count_slice(std::uint32_t units) noexcept {
  ++stats_.slices;
  stats_.max_units_in_slice = std::max(stats_.max_units_in_slice, units);
}

}  // namespace ringlet::pddl
