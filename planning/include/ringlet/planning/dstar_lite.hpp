#pragma once
// D* Lite, the optimized version (Koenig & Likhachev 2002, Fig. 4), over a GridGraph.
//
// It searches backwards from the goal, so when the robot moves (move_start) or step costs change
// (vertex_changed) it repairs only the vertices the change reaches instead of searching again.
// It is sliced: step(max_pops) resumes the search where the previous slice stopped and does at
// most max_pops queue pops, a deterministic amount of work, so a lockstep run is a pure function of
// its inputs. All storage is sized by reserve() at start-up; nothing after it allocates.
//
// The plan is ready when step() returns kReady: plan_cost() is then the cost of the best path and
// extract_path()/next_vertex() follow it. While kSearching, the g-values are half-computed and
// must not be acted on.
#include <cstdint>
#include <span>
#include <vector>

#include "ringlet/planning/grid_graph.hpp"
#include "ringlet/planning/search_queue.hpp"

namespace ringlet::planning {

enum class SearchStatus : std::uint8_t {
  kIdle,         // no search begun
  kSearching,    // the last slice ran out of pops: call step() again
  kReady,        // g(start) is the optimal cost, the path can be followed
  kUnreachable,  // the search finished and no path leads from start to goal
};

/// Work done since begin(): what the bench and the whiteboard report.
struct SearchCounters {
  std::int64_t pops = 0;          // vertices taken off the queue (the slice budget's unit)
  std::int64_t expansions = 0;    // pops whose neighbours were examined (the paper's expansions)
  std::int64_t edge_changes = 0;  // step costs found changed by vertex_changed()
};

class DStarLite {
 public:
  /// Sizes every array for graphs of up to `max_vertices` vertices (allocates: start-up only).
  void reserve(int max_vertices);
  [[nodiscard]] int capacity() const noexcept { return static_cast<int>(g_.size()); }

  /// Begins a new search on `graph` (at most capacity() vertices; it must outlive the search).
  /// O(vertices), no allocation. Returns false, and leaves the planner idle, when the graph or
  /// the vertices do not fit.
  bool begin(const GridGraph& graph, int start, int goal) noexcept;
  /// Resumes the search for at most `max_pops` pops (≥ 1).
  SearchStatus step(std::int64_t max_pops) noexcept;
  /// The robot is now at `start` (moving along the plan or not): keys stay valid through km.
  void move_start(int start) noexcept;
  /// Step costs out of `v` or out of any of its 8 neighbours may have changed (a region's
  /// occupancy changed): re-reads them and repairs what depends on them.
  void vertex_changed(int v) noexcept;
  /// The step costs out of `v` (only) may have changed: re-reads them and repairs. For cost models
  /// whose edges read more than the two regions they join (the learned one), the caller names
  /// every vertex whose steps read a changed region.
  void edges_changed(int v) noexcept;

  [[nodiscard]] SearchStatus status() const noexcept { return status_; }
  [[nodiscard]] int start() const noexcept { return start_; }
  [[nodiscard]] int goal() const noexcept { return goal_; }
  [[nodiscard]] Cost g(int v) const noexcept { return g_[static_cast<std::size_t>(v)]; }
  [[nodiscard]] Cost rhs(int v) const noexcept { return rhs_[static_cast<std::size_t>(v)]; }
  /// The cost of the plan from start to goal (kInfiniteCost unless kReady). It is rhs(start),
  /// the best step cost + g over start's successors: the optimized search stops once no queued
  /// key is below start's, which may leave start itself overconsistent (g > rhs).
  [[nodiscard]] Cost plan_cost() const noexcept { return status_ == SearchStatus::kReady ? rhs(start_) : kInfiniteCost; }
  [[nodiscard]] const SearchCounters& counters() const noexcept { return counters_; }
  /// The key of `v` now, and the queue's smallest key (an empty queue: infinite): a vertex with
  /// g == rhs and a key not above it has g equal to its true goal distance.
  [[nodiscard]] SearchKey key(int v) const noexcept;
  [[nodiscard]] SearchKey top_key() const noexcept;

  /// The plan from start to goal into `out` (both ends included); returns the number of vertices,
  /// 0 when no plan is ready or `out` is too short. Ties go to the lower direction index.
  int extract_path(std::span<int> out) noexcept;
  /// The vertex after start on the plan: start itself at the goal, −1 when no plan is ready.
  int next_vertex() noexcept;

 private:
  [[nodiscard]] Cost cost(int s, int k) noexcept;
  [[nodiscard]] Cost best_rhs(int s) noexcept;
  /// The neighbour minimising step cost + g (the lower direction on ties), −1 if none is finite.
  [[nodiscard]] int best_successor(int s) noexcept;
  [[nodiscard]] bool search_done() const noexcept;
  void update_vertex(int u) noexcept;
  /// Re-reads u's step costs, if they were ever read, and repairs rhs(u) for the changed ones.
  void reread(int u) noexcept;
  [[nodiscard]] Cost& g_at(int v) noexcept { return g_[static_cast<std::size_t>(v)]; }
  [[nodiscard]] Cost& rhs_at(int v) noexcept { return rhs_[static_cast<std::size_t>(v)]; }

  const GridGraph* graph_ = nullptr;
  int start_ = -1, goal_ = -1, last_ = -1;
  Cost km_ = 0;
  SearchStatus status_ = SearchStatus::kIdle;
  SearchCounters counters_;
  std::vector<Cost> g_, rhs_;
  std::vector<Cost> cost_;             // 8 step costs per vertex, read from the graph lazily
  std::vector<std::uint8_t> cached_;   // whether a vertex's step costs were read
  SearchQueue queue_;
};

}  // namespace ringlet::planning
