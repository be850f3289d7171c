#pragma once
// What the PlanExecute machine (plan, execute, re-plan: Mi-Pal Fig. 6) needs besides the
// whiteboard: its parameters, and the laser test that decides an obstacle stands on the leg it
// is driving. Pure functions, no allocation: the machine calls them in its ringlets.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "ringlet/behaviour/move_to_waypoint.hpp"
#include "ringlet/hal/geometry.hpp"

namespace ringlet::behaviour {

struct PlanExecuteParams {
  std::string planner = "lama";  ///< LOAD_PLANNER's argument
  std::string problem;           ///< LOAD_PDDL's argument
  int depth = 0;                 ///< START_PLANNER's and RE-PLAN's horizon (0: none)
  double detect_range = 2.0;     ///< m: a return this close ahead on the leg is an obstacle
  double corridor = 0.5;         ///< m: ... within this of the leg's line
  double tolerance = 0.3;        ///< m: a place counts as reached this close
  MoveToWaypointParams follower{};
};

/// The nearest laser return (beam i at angle_min + i · increment from the heading, clockwise
/// positive; range_mm 0: nothing seen) that lies ahead on the leg from `pose` to `target`: its
/// projection on the leg between 0 and min(range, the leg's length), within `corridor` of its
/// line. Returns false when there is none; else its world position in ox, oy.
[[nodiscard]] bool obstacle_on_leg(std::span<const std::uint16_t> range_mm, double angle_min, double increment,
                                   const hal::Pose2& pose, const Waypoint& target, double range, double corridor,
                                   double& ox, double& oy) noexcept;

/// The n-th word (from 0) of space-separated text, or "".
[[nodiscard]] std::string_view nth_word(std::string_view text, int n) noexcept;

}  // namespace ringlet::behaviour
