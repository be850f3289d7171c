#pragma once
// The learned cost model of Powers & Balch (§III-C): the expected speed of a transition is what
// the kNN regressor predicts from its features (experience.hpp), clamped to [0, top speed].
//
// Walls. The robot never drives through a wall, so no experience ever says "speed 0 here", and a
// kNN model asked about a wall answers with the speed of the nearest situations it knows, which
// are passable ones. So a hard rule stays in force whatever the model says: a transition whose
// `from` or `to` region holds more than `wall_occupied` occupied cells is impassable. It is the
// binary model's rule with a higher limit: the binary model's max_occupied (2 of 16 cells) is
// exactly what closes the dense-but-passable wood, where the laser marks a few cells per region
// (a tree's visible face); a wall crossing a region marks a line of cells. Between the two limits
// the model decides.
//
// Caches. A kNN query costs 10-21 us at n = 5000 (tests/bench/bench_planning.cpp) and a D* Lite
// pop may read 64 step costs, so predictions are kept per edge (region x 8 directions, sized at
// start-up) and memoized by feature vector (most edges share theirs). The per-edge cache is invalidated precisely by the caller:
//   - region_changed(r): every edge whose features read region r (the feature window around both
//     ends: feature_offset()), whatever its direction; it also names the edges' source vertices,
//     which D* Lite must re-read (DStarLite::edges_changed);
//   - edges_from_changed(v): the robot entered or left v, whose own count the edges out of it
//     ignore while it is there (RegionGraph::transition).
//
// A new index (KnnRegressor::rebuild off the cycle, then here): begin_refresh() starts
// recomputing every cached edge with the waiting index (KnnRegressor::predict_pending), in slices
// bounded by a count of predictions (refresh()); meanwhile the old cached costs stay in force, so
// the plan D* Lite holds stays consistent with the costs it read. finish_refresh() publishes the
// index and switches every recomputed edge at once, and names the vertices whose out-edges
// changed, for D* Lite's incremental repair: the planner never starts again from scratch.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ringlet/planning/cost_model.hpp"
#include "ringlet/planning/feature_memo.hpp"
#include "ringlet/planning/knn_regressor.hpp"
#include "ringlet/planning/occupancy_grid.hpp"

namespace ringlet::planning {

class RegionGraph;

struct LearnedCostParams {
  double top_speed = 2.0;       // m/s: predictions are clamped to it
  int wall_occupied = 3;        // a region holding more occupied cells is impassable (a wall)
  std::size_t memo_capacity = 4096;  // distinct feature vectors remembered per index

  /// Empty when usable, else what is wrong (names the field).
  [[nodiscard]] std::string validate() const;
};

class LearnedCostModel final : public CostModel {
 public:
  /// The most source vertices region_changed() can name: a region is read by at most 10 slots in
  /// each of 8 directions, all within two regions of it.
  static constexpr std::size_t kMaxSources = 25;

  /// Sizes the caches for `map`'s regions (allocates: start-up). `knn` must outlive the model.
  LearnedCostModel(KnnRegressor& knn, const LearnedCostParams& p, const MapConfig& map);

  [[nodiscard]] double expected_speed(const RegionTransition& t) const noexcept override;
  [[nodiscard]] double top_speed() const noexcept override { return params_.top_speed; }
  [[nodiscard]] const LearnedCostParams& params() const noexcept { return params_; }

  /// Region `region`'s count changed: forgets every edge whose features read it. Writes the
  /// vertices those edges leave (each once) into `sources` (room for kMaxSources) and returns
  /// how many.
  std::size_t region_changed(int region, std::span<int> sources) noexcept;
  /// The robot entered or left region `v`: forgets the edges out of it.
  void edges_from_changed(int v) noexcept;

  /// Starts recomputing the cached edges with the index KnnRegressor::rebuild() left waiting;
  /// false (nothing started) when none waits or a refresh is under way.
  bool begin_refresh() noexcept;
  [[nodiscard]] bool refreshing() const noexcept { return refreshing_; }
  /// Resumes the refresh through `graph` (the graph this model costs) for at most
  /// `max_predictions` predictions and `max_edges` edges; true when every edge has been visited.
  bool refresh(const RegionGraph& graph, std::int64_t max_predictions, std::int64_t max_edges) noexcept;
  /// Publishes the waiting index and switches every recomputed edge to its new speed, at once.
  /// Returns the vertices whose out-edges changed (valid until the next call): the caller hands
  /// each to DStarLite::edges_changed.
  std::span<const int> finish_refresh() noexcept;

  /// kNN queries made (cache and memo misses, refresh included): what the planner's modelled cost
  /// charges.
  [[nodiscard]] std::uint64_t predictions() const noexcept { return predictions_; }
  /// Edges in the cache: finish_refresh() sweeps them all.
  [[nodiscard]] std::size_t edge_count() const noexcept { return state_.size(); }
  /// Edges the refresh has visited: modelled work too.
  [[nodiscard]] std::uint64_t refresh_edges() const noexcept { return refresh_edges_; }

 private:
  enum : std::uint8_t { kValid = 1, kNext = 2 };
  [[nodiscard]] double clamp(double s) const noexcept;
  void forget(std::size_t edge) noexcept { state_[edge] = 0; }

  KnnRegressor& knn_;
  LearnedCostParams params_;
  int regions_x_, regions_y_;
  mutable std::vector<double> speed_;         // per edge (region * 8 + direction)
  std::vector<double> next_;                  // the waiting index's speed, during a refresh
  mutable std::vector<std::uint8_t> state_;   // kValid, kNext
  mutable FeatureMemo memo_;                  // the published index's predictions
  FeatureMemo next_memo_;                     // the waiting index's
  std::vector<int> changed_;                  // finish_refresh()'s answer, one entry per region
  bool refreshing_ = false;
  std::size_t cursor_ = 0;                    // the next edge the refresh visits
  mutable std::uint64_t predictions_ = 0;
  std::uint64_t refresh_edges_ = 0;
};

}  // namespace ringlet::planning
