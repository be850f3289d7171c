#pragma once
// What ringlet-plan-bench measures, as functions the tests call too:
//   check   — D* Lite (and A*) on a fully known map against the .scen file's optimal lengths;
//   replan  — a robot that discovers obstacles as it drives (free-space assumption, a sensing
//             radius), replanning with D* Lite and, in the same run from the same positions,
//             with A* from scratch; expansions (deterministic) and host time (reported only).
#include <cstdint>
#include <string>
#include <vector>

#include "ringlet/planning/movingai.hpp"

namespace ringlet::planning::bench {

struct CheckRow {
  int line = 0;             // in the .scen file
  double optimal = 0.0;     // the file's, in cells
  double dstar = 0.0;       // D* Lite's plan cost, in cells (infinite: no path)
  double astar = 0.0;       // A*'s
  std::int64_t dstar_expansions = 0, astar_expansions = 0;
};

/// Every problem of a .scen on its map (all of it known). Throws MovingAiError for a problem
/// that does not fit the map.
std::vector<CheckRow> check_scenarios(const MovingAiMap& map, const std::vector<MovingAiProblem>& problems);

struct ReplanOptions {
  int sensor_radius = 5;  // cells: everything within this Euclidean distance becomes known
};

struct ReplanRow {
  int line = 0;
  bool reached = false;             // the robot got to the goal (else the goal is walled off)
  int moves = 0;                    // cells driven
  int replans = 0;                  // times new obstacles were seen (both planners replanned)
  double travelled = 0.0;           // octile length driven
  std::int64_t dstar_expansions = 0, astar_expansions = 0;  // including the first search
  double dstar_seconds = 0.0, astar_seconds = 0.0;          // host time, for the report only
  std::vector<int> first_plan;      // cells of the first plan (the picture)
  std::vector<int> trajectory;      // cells driven, start to end
};

/// One problem driven from start to goal; throws std::runtime_error if the planners ever
/// disagree on the cost of the best known path (the run then proves nothing).
ReplanRow replan(const MovingAiMap& map, const MovingAiProblem& problem, const ReplanOptions& options);

/// An SVG of one replanning run: true obstacles faint, the ones discovered dark, the first plan
/// dashed, the trajectory solid.
std::string replan_svg(const MovingAiMap& map, const ReplanRow& row, const ReplanOptions& options, const std::string& title);

}  // namespace ringlet::planning::bench
