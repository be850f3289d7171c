#pragma once
// A grid graph whose every directed step cost is set by the test, and Dijkstra from scratch over
// it: the independent answer D* Lite is checked against.
#include <queue>
#include <random>
#include <utility>
#include <vector>

#include "ringlet/planning/grid_graph.hpp"

namespace ringlet::planning::testing {

class TableGraph final : public GridGraph {
 public:
  TableGraph(int w, int h, Cost min_step) : w_(w), h_(h), min_(min_step), cost_(static_cast<std::size_t>(w * h * 8), kInfiniteCost) {}
  [[nodiscard]] int width() const noexcept override { return w_; }
  [[nodiscard]] int height() const noexcept override { return h_; }
  [[nodiscard]] Cost step_cost(int v, int k) const noexcept override { return cost_[static_cast<std::size_t>(v * 8 + k)]; }
  [[nodiscard]] Cost min_step_cost() const noexcept override { return min_; }
  /// Sets the cost of v's step k (ignored off the grid: that step is always infinite).
  void set(int v, int k, Cost c) {
    if (neighbour(v, k) >= 0) cost_[static_cast<std::size_t>(v * 8 + k)] = c;
  }
  /// A random cost for a step: infinite with probability p_block, else at least the heuristic's
  /// weight for it (so the heuristic stays consistent); often exactly a small multiple of it, so
  /// that ties between paths, and between keys, are common.
  static Cost random_cost(std::mt19937& rng, int k, Cost min_step, double p_block) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    if (u(rng) < p_block) return kInfiniteCost;
    const Cost base = is_diagonal(k) ? diagonal_bound(min_step) : min_step;
    if (u(rng) < 0.6) return base * std::uniform_int_distribution<Cost>(1, 3)(rng);
    return base + std::uniform_int_distribution<Cost>(0, 3 * base)(rng);
  }
  void randomise_vertex(int v, std::mt19937& rng, double p_block) {
    for (int k = 0; k < 8; ++k) set(v, k, random_cost(rng, k, min_, p_block));
  }

 private:
  int w_, h_;
  Cost min_;
  std::vector<Cost> cost_;
};

/// The cost of the cheapest path from every vertex to `goal`, Dijkstra backwards from scratch.
inline std::vector<Cost> distances_to(const GridGraph& g, int goal) {
  std::vector<Cost> d(static_cast<std::size_t>(g.vertex_count()), kInfiniteCost);
  using Item = std::pair<Cost, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  d[static_cast<std::size_t>(goal)] = 0;
  open.push({0, goal});
  while (!open.empty()) {
    const auto [du, u] = open.top();
    open.pop();
    if (du > d[static_cast<std::size_t>(u)]) continue;
    for (int k = 0; k < 8; ++k) {  // predecessors s of u: the step from s in direction opposite(k)
      const int s = g.neighbour(u, k);
      if (s < 0) continue;
      const Cost c = add_cost(g.step_cost(s, opposite(k)), du);
      if (c < d[static_cast<std::size_t>(s)]) {
        d[static_cast<std::size_t>(s)] = c;
        open.push({c, s});
      }
    }
  }
  return d;
}

}  // namespace ringlet::planning::testing
