#pragma once
// RE-PLAN's source, read in the cycle: an atom as text, "at robot1 p21" or "(at robot1 p21)",
// found among the task's facts by name, and put into a state in place of the atoms of the same
// predicate and first argument (the robot is at one place: "at robot1 p21" replaces
// "at robot1 p11"). No allocation; the loops are bounded by the task's facts.
#include <cstdint>
#include <string_view>

#include "ringlet/pddl/task.hpp"

namespace ringlet::pddl {

/// The fact `text` names in `task`, or -1 (an unknown predicate or object, a wrong arity, or a
/// fact grounding never reached). Names compare case-insensitively, as PDDL's do.
[[nodiscard]] std::int32_t find_fact(const Task& task, std::string_view text) noexcept;

/// Clears in `state` every fact with `fact`'s predicate and first argument, then sets `fact`.
void put_source(const Task& task, State state, std::int32_t fact) noexcept;

}  // namespace ringlet::pddl
