#pragma once
// Plans as text: one ground action per line, "(action object...)", `;` comments; what the CLI
// prints and reads back with --validate, and what VAL-style tools exchange.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ringlet/pddl/parser.hpp"
#include "ringlet/pddl/task.hpp"

namespace ringlet::pddl {

struct PlanStep {
  std::string action;
  std::vector<std::string> args;
  Location where;
};

[[nodiscard]] Parsed<std::vector<PlanStep>> parse_plan(std::string_view text, const std::string& file);

/// A planner's plan (operator indices of `task`) as steps by name.
[[nodiscard]] std::vector<PlanStep> plan_steps(const Task& task, std::span<const std::int32_t> plan);

/// "(action a b)".
[[nodiscard]] std::string step_text(const PlanStep& step);

}  // namespace ringlet::pddl
