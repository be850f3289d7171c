#pragma once
// The search space every planner in planning/ runs over: an 8-connected grid of vertices with
// directed step costs. Both the region graph of Powers & Balch §III-B (one vertex per region) and
// a MovingAI benchmark map (one vertex per cell) are such grids, so D* Lite, A* and the tests see
// one interface.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

namespace ringlet::planning {

/// Path costs are integers (a graph chooses the unit: nanoseconds of driving, 2^-32 cells):
/// sums are exact and the same on every host, so equal keys are equal. Floating-point sums are
/// not: a tie between two keys that rounds the wrong way ends a D* Lite search early.
using Cost = std::int64_t;
/// No path, an impassable step. Finite costs stay below it, and add_cost() saturates at it.
inline constexpr Cost kInfiniteCost = std::numeric_limits<Cost>::max() / 4;
inline constexpr double kSqrt2 = 1.4142135623730951;

[[nodiscard]] constexpr Cost add_cost(Cost a, Cost b) noexcept {
  return a >= kInfiniteCost || b >= kInfiniteCost || a + b >= kInfiniteCost ? kInfiniteCost : a + b;
}

/// The 8 steps, counter-clockwise from +x: directions k and (k + 4) % 8 are opposite; odd
/// directions are diagonal.
struct GridStep {
  int dx, dy;
};
inline constexpr std::array<GridStep, 8> kGridSteps{{{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};
inline constexpr int kGridDirections = 8;

[[nodiscard]] constexpr int opposite(int k) noexcept { return (k + 4) % kGridDirections; }
[[nodiscard]] constexpr bool is_diagonal(int k) noexcept { return (k & 1) != 0; }

/// Octile distance: (hi − lo) straight steps of `straight` and lo diagonal ones of `diagonal`.
[[nodiscard]] constexpr Cost octile(int dx, int dy, Cost straight, Cost diagonal) noexcept {
  const int ax = dx < 0 ? -dx : dx, ay = dy < 0 ? -dy : dy;
  const int lo = ax < ay ? ax : ay, hi = ax < ay ? ay : ax;
  return straight * (hi - lo) + diagonal * lo;
}
/// Octile distance in cells (straight 1, diagonal √2), for reports.
[[nodiscard]] inline double octile_cells(int dx, int dy) noexcept {
  const int ax = std::abs(dx), ay = std::abs(dy);
  const int lo = ax < ay ? ax : ay, hi = ax < ay ? ay : ax;
  return static_cast<double>(hi - lo) + kSqrt2 * static_cast<double>(lo);
}

class GridGraph {
 public:
  GridGraph() = default;
  GridGraph(const GridGraph&) = delete;
  GridGraph& operator=(const GridGraph&) = delete;
  virtual ~GridGraph() = default;

  [[nodiscard]] virtual int width() const noexcept = 0;
  [[nodiscard]] virtual int height() const noexcept = 0;
  /// The cost of the move from vertex `v` one step in direction `k` (kGridSteps): kInfiniteCost
  /// when the move is not allowed or leaves the grid; else at least min_step_cost() straight and
  /// min_diagonal_cost() diagonally.
  [[nodiscard]] virtual Cost step_cost(int v, int k) const noexcept = 0;
  /// Lower bounds on the cost of a straight (≥ 1) and of a diagonal step: the octile heuristic's
  /// weights, which keep it admissible and consistent.
  [[nodiscard]] virtual Cost min_step_cost() const noexcept = 0;
  [[nodiscard]] Cost min_diagonal_cost() const noexcept { return diagonal_bound(min_step_cost()); }
  /// floor(√2 · straight): what a graph's diagonal steps must cost at least.
  [[nodiscard]] static Cost diagonal_bound(Cost straight) noexcept {
    return static_cast<Cost>(std::floor(static_cast<double>(straight) * kSqrt2));
  }

  [[nodiscard]] int vertex_count() const noexcept { return width() * height(); }
  [[nodiscard]] int vertex(int x, int y) const noexcept { return y * width() + x; }
  [[nodiscard]] int x_of(int v) const noexcept { return v % width(); }
  [[nodiscard]] int y_of(int v) const noexcept { return v / width(); }
  [[nodiscard]] bool inside(int x, int y) const noexcept { return x >= 0 && y >= 0 && x < width() && y < height(); }
  /// The neighbour of `v` in direction `k`, or -1 off the grid.
  [[nodiscard]] int neighbour(int v, int k) const noexcept {
    const int x = x_of(v) + kGridSteps[static_cast<std::size_t>(k)].dx;
    const int y = y_of(v) + kGridSteps[static_cast<std::size_t>(k)].dy;
    return inside(x, y) ? vertex(x, y) : -1;
  }
  /// The octile heuristic between two vertices, weighted by the step-cost lower bounds.
  [[nodiscard]] Cost heuristic(int a, int b) const noexcept {
    return octile(x_of(a) - x_of(b), y_of(a) - y_of(b), min_step_cost(), min_diagonal_cost());
  }
};

}  // namespace ringlet::planning
