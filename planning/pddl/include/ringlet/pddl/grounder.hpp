#pragma once
// Grounding a parsed domain + problem into a Task in an Arena, on the service thread. Only what
// relaxed reachability can reach is instantiated (actions whose positive preconditions can all
// become true, ignoring deletes), so grounding does not blow up on objects that never meet;
// static predicates (no action changes them) are decided here and vanish from the task.
#include <cstddef>
#include <string>

#include "ringlet/pddl/arena.hpp"
#include "ringlet/pddl/ast.hpp"
#include "ringlet/pddl/task.hpp"

namespace ringlet::pddl {

enum class GroundStatus { kOk, kOutOfMemory };

struct GroundResult {
  GroundStatus status = GroundStatus::kOk;
  Task task;            ///< valid when kOk; lives in the arena
  std::string message;  ///< kOutOfMemory: what overflowed
};

/// Builds the task into `arena` (reset first). Grounding stops as soon as the operators or facts
/// found could no longer fit in the arena, so its temporary containers stay bounded too.
[[nodiscard]] GroundResult ground(const Domain& domain, const Problem& problem, Arena& arena);

}  // namespace ringlet::pddl
