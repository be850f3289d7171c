#pragma once
// Our own VAL: a plan checked against the parsed domain and problem, independently of the
// grounder and the planners (it substitutes into the action schemas and tracks the state as a
// set of atoms). A failure says which step and why: an unknown action or object, a wrong type
// or arity, the first precondition that does not hold, or the goal literal that does not hold
// at the end.
#include <string>
#include <vector>

#include "ringlet/pddl/ast.hpp"
#include "ringlet/pddl/plan_file.hpp"

namespace ringlet::pddl {

struct Validation {
  bool valid = false;
  int step = 0;        ///< the failing step, from 1; 0 when the goal fails (or the plan is valid)
  std::string reason;  ///< located where the step came from a file
};

[[nodiscard]] Validation validate(const Domain& domain, const Problem& problem, const std::vector<PlanStep>& plan);

}  // namespace ringlet::pddl
