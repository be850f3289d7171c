#pragma once
// The graph overlaid on the map (Powers & Balch §III-B): one vertex at the centre of each region,
// edges between contiguous regions (8-connected), each costing the time to drive it: distance ÷
// the cost model's expected speed (infinite at speed 0), in nanoseconds.
//
// A diagonal edge runs through the corner the two regions share, so it is allowed only where the
// reactive layer could also pass by the side: both straight transitions from its start towards
// the sides must be traversable (the same no-corner-cutting rule as the MovingAI benchmarks).
//
// The robot's own region never keeps it in: its occupied cells are not counted for transitions
// out of it (the robot is there already, and driving along a wall fills the region it is in).
// The planner says where the robot is with set_robot_region() and then tells D* Lite that the old
// and the new region changed.
#include "ringlet/planning/cost_model.hpp"
#include "ringlet/planning/grid_graph.hpp"
#include "ringlet/planning/occupancy_grid.hpp"

namespace ringlet::planning {

class RegionGraph final : public GridGraph {
 public:
  /// Both must outlive the graph; their state is read at every step_cost().
  RegionGraph(const OccupancyGrid& map, const CostModel& model) noexcept : map_(map), model_(model) {}

  [[nodiscard]] int width() const noexcept override { return map_.config().regions_x(); }
  [[nodiscard]] int height() const noexcept override { return map_.config().regions_y(); }
  static constexpr double kCostPerSecond = 1e9;  // Cost unit: nanoseconds

  [[nodiscard]] Cost step_cost(int v, int k) const noexcept override;
  /// A straight step at top speed, rounded down.
  [[nodiscard]] Cost min_step_cost() const noexcept override;
  [[nodiscard]] static double seconds(Cost c) noexcept { return static_cast<double>(c) / kCostPerSecond; }
  /// The region the robot is in (−1: none).
  void set_robot_region(int region) noexcept { robot_region_ = region; }
  [[nodiscard]] int robot_region() const noexcept { return robot_region_; }
  /// The transition from region v one step in direction k, as the cost model sees it (the robot's
  /// region counts as empty when left); `to` is −1 off the grid. What an experience is built from.
  [[nodiscard]] RegionTransition transition(int v, int k) const noexcept;

 private:
  /// The clamped expected speed from region v one step in direction k (0: impassable).
  [[nodiscard]] double speed(int v, int k) const noexcept;

  const OccupancyGrid& map_;
  const CostModel& model_;
  int robot_region_ = -1;
};

}  // namespace ringlet::planning
