#pragma once
// A* from scratch over a GridGraph: the baseline D* Lite is measured against when obstacles are
// discovered along the way (Koenig & Likhachev's comparison). It uses the same octile heuristic,
// the same queue and the same definition of an expansion (a vertex taken off the queue whose
// neighbours are examined), so expansion counts compare like with like.
#include <cstdint>
#include <span>
#include <vector>

#include "ringlet/planning/grid_graph.hpp"
#include "ringlet/planning/search_queue.hpp"

namespace ringlet::planning {

class AStar {
 public:
  /// Sizes every array for graphs of up to `max_vertices` vertices (allocates: start-up only).
  void reserve(int max_vertices);

  /// Searches from `start` to `goal`; returns the path cost (kInfiniteCost: no path) and adds
  /// its expansions to expansions(). Vertices outside the graph give kInfiniteCost.
  Cost search(const GridGraph& graph, int start, int goal) noexcept;
  /// The path found by the last search, start to goal, into `out`; 0 if none or `out` is short.
  int extract_path(std::span<int> out) const noexcept;
  [[nodiscard]] std::int64_t expansions() const noexcept { return expansions_; }

 private:
  std::vector<Cost> g_;
  std::vector<int> parent_;
  std::vector<std::uint8_t> closed_;
  SearchQueue open_;
  int start_ = -1, goal_ = -1;
  bool found_ = false;
  std::int64_t expansions_ = 0;
};

}  // namespace ringlet::planning
