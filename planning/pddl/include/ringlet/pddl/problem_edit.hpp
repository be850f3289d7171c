#pragma once
// Changes the planner service makes to a loaded problem on its service thread (allocation is
// allowed there, never in the cycle): the believed state written back as the problem's initial
// state, and IS_OBSTACLE_KNOWN's obstacle added as (blocked a b) facts. After either the problem
// is grounded again and the new task handed to the cycle at a defined frame.
#include <span>
#include <string>
#include <vector>

#include "ringlet/pddl/ast.hpp"
#include "ringlet/pddl/task.hpp"

namespace ringlet::pddl {

/// Where a place object of the problem lies in the world (m): [pddl] places. IS_OBSTACLE_KNOWN
/// maps a position to the connections it blocks through these, and NEXT_ACTION's reply gives the
/// position of each argument that is a place.
struct Place {
  std::string name;
  double x = 0.0;
  double y = 0.0;
};

/// Replaces the initial atoms of every predicate an action can change by the facts true in
/// `state` of `task` (grounded from `domain` and an earlier version of `problem`, with the same
/// objects); the atoms of static predicates stay as they are.
void set_initial_state(const Domain& domain, Problem& problem, const Task& task, ConstState state);

struct ObstacleEdit {
  bool ok = false;     ///< false: nothing could be decided (message says why)
  bool known = false;  ///< every connection the obstacle lies on was already blocked
  std::vector<Atom> added;
  std::string message;  ///< "(blocked p21 p31) (blocked p31 p21) added", or why not
};

/// IS_OBSTACLE_KNOWN(x, y): the connections `(connected a b)` of the problem's initial state
/// whose straight segment between the places a and b passes within `radius` m of (x, y); each
/// one not yet `(blocked a b)` gets that atom. The domain must have both predicates, binary.
[[nodiscard]] ObstacleEdit add_obstacle(const Domain& domain, Problem& problem, std::span<const Place> places,
                                        double x, double y, double radius);

}  // namespace ringlet::pddl
