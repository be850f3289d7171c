#include "ringlet/planning/astar.hpp"

#include <algorithm>

namespace ringlet::planning {

void AStar::reserve(int max_vertices) {
  const auto n = static_cast<std::size_t>(std::max(max_vertices, 0));
  g_.assign(n, kInfiniteCost);
  parent_.assign(n, -1);
  closed_.assign(n, 0);
  open_.reserve(static_cast<int>(n));
}

Cost AStar::search(const GridGraph& graph, int start, int goal) noexcept {
  found_ = false;
  const int n = graph.vertex_count();
  if (n > static_cast<int>(g_.size()) || start < 0 || start >= n || goal < 0 || goal >= n) return kInfiniteCost;
  const auto count = static_cast<std::size_t>(n);
  std::fill_n(g_.begin(), count, kInfiniteCost);
  std::fill_n(parent_.begin(), count, -1);
  std::fill_n(closed_.begin(), count, std::uint8_t{0});
  open_.clear();
  start_ = start;
  goal_ = goal;
  g_[static_cast<std::size_t>(start)] = 0;
  open_.push_or_update(start, {graph.heuristic(start, goal), 0});
  while (!open_.empty()) {
    const int u = open_.pop();
    if (u == goal) {
      found_ = true;
      return g_[static_cast<std::size_t>(u)];
    }
    closed_[static_cast<std::size_t>(u)] = 1;
    ++expansions_;
    const Cost gu = g_[static_cast<std::size_t>(u)];
    for (int k = 0; k < kGridDirections; ++k) {
      const int w = graph.neighbour(u, k);
      if (w < 0 || closed_[static_cast<std::size_t>(w)] != 0) continue;
      const Cost c = add_cost(gu, graph.step_cost(u, k));
      if (c < g_[static_cast<std::size_t>(w)]) {
        g_[static_cast<std::size_t>(w)] = c;
        parent_[static_cast<std::size_t>(w)] = u;
        open_.push_or_update(w, {add_cost(c, graph.heuristic(w, goal)), c});
      }
    }
  }
  return kInfiniteCost;
}

int AStar::extract_path(std::span<int> out) const noexcept {
  if (!found_) return 0;
  std::size_t n = 0;
  for (int v = goal_; v >= 0; v = parent_[static_cast<std::size_t>(v)]) {
    if (n == out.size()) return 0;
    out[n++] = v;
    if (v == start_) break;
  }
  std::reverse(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n));
  return static_cast<int>(n);
}

}  // namespace ringlet::planning
