#pragma once
// The deliberative layer in the cycle (Powers & Balch §III-B): the laser scan goes into the
// occupancy grid through the pose, and D* Lite plans over the map's regions to the mission's
// current target (MissionStatus, posted by the Navigate machine), in slices.
//
// Each activation marks the newest scan (and the feet of the robots vision saw since the last
// activation, when the table runs vision: obstacles as laser hits are), tells D* Lite where the robot now is and which regions
// changed, and resumes the search for at most [planner] pops_per_slice queue pops: a
// deterministic amount of work, so a lockstep run is a pure function of seed and configuration.
// On the real clock the activation's deadline is a backstop, checked every 64 pops. A plan becomes
// visible (Plan, status ready) in the activation whose slice finishes it; until then the last
// ready plan's waypoint and path stay posted (has_plan), and a search that finds no way posts
// unreachable with no plan. The waypoint is the centre of the next region on the plan (the
// paper's transition model), or the target itself when the next region is the target's (or the
// robot is in it already): aiming at that region's centre first would overshoot the target.
//
// Everything (grid, regions, the search's arrays, the path) is sized at start-up from [planner].
#include <memory>
#include <vector>

#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"
#include "ringlet/planning/dstar_lite.hpp"
#include "ringlet/planning/region_graph.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

class PlannerTask final : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{"planner", kTypeNames<wb::Pose, wb::LaserScan, wb::MissionStatus>,
                                                kTypeNames<wb::Plan>, here(), kTypeNames<wb::RobotDetections>};
  /// The board's cost: a fixed part, every beam placed in the grid, every queue pop.
  static constexpr hal::Nanos kBaseCost{20'000};
  static constexpr hal::Nanos kCostPerBeam{100};
  static constexpr hal::Nanos kCostPerPop{800};

  static std::unique_ptr<executive::Task> make(TaskServices& services);
  PlannerTask(const PlannerSettings& settings, wb::Whiteboard& board, bool realtime_backstop);
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] hal::Nanos modelled_cost() const noexcept override { return cost_; }

  [[nodiscard]] const planning::OccupancyGrid& map() const noexcept { return map_; }

 private:
  int integrate_scan(const wb::Pose& pose) noexcept;
  void integrate_robots(const wb::Pose& pose) noexcept;
  void mark(double wx, double wy) noexcept;
  void post_plan(planning::SearchStatus status, const wb::MissionStatus& mission) noexcept;

  PlannerSettings settings_;
  wb::Whiteboard& board_;
  bool realtime_backstop_;
  planning::OccupancyGrid map_;
  planning::BinaryCostModel model_;
  planning::RegionGraph graph_;
  planning::DStarLite search_;
  std::vector<int> path_;  // one entry per region: the longest path there can be
  wb::LaserScan scan_{};
  wb::Plan plan_{};
  bool searching_goal_ = false;  // a search for plan_.goal_x/y has begun
  std::uint64_t robots_seen_ = 0;  // the last RobotDetections generation marked
  hal::Nanos cost_{kBaseCost};
};

}  // namespace ringlet::firmware
