#include "ringlet/planning/dstar_lite.hpp"

#include <algorithm>

namespace ringlet::planning {

void DStarLite::reserve(int max_vertices) {
  const auto n = static_cast<std::size_t>(std::max(max_vertices, 0));
  g_.assign(n, kInfiniteCost);
  rhs_.assign(n, kInfiniteCost);
  cost_.assign(n * kGridDirections, kInfiniteCost);
  cached_.assign(n, 0);
  queue_.reserve(static_cast<int>(n));
  graph_ = nullptr;
  status_ = SearchStatus::kIdle;
}

bool DStarLite::begin(const GridGraph& graph, int start, int goal) noexcept {
  const int n = graph.vertex_count();
  if (n <= 0 || n > capacity() || start < 0 || start >= n || goal < 0 || goal >= n) {
    graph_ = nullptr;
    status_ = SearchStatus::kIdle;
    return false;
  }
  graph_ = &graph;
  const auto count = static_cast<std::size_t>(n);
  std::fill_n(g_.begin(), count, kInfiniteCost);
  std::fill_n(rhs_.begin(), count, kInfiniteCost);
  std::fill_n(cached_.begin(), count, std::uint8_t{0});
  queue_.clear();
  start_ = start;
  last_ = start;
  goal_ = goal;
  km_ = 0;
  counters_ = {};
  rhs_at(goal) = 0;
  queue_.push_or_update(goal, {graph.heuristic(start, goal), 0});
  status_ = SearchStatus::kSearching;
  return true;
}

Cost DStarLite::cost(int s, int k) noexcept {
  const auto base = static_cast<std::size_t>(s) * kGridDirections;
  if (cached_[static_cast<std::size_t>(s)] == 0) {
    for (int d = 0; d < kGridDirections; ++d) cost_[base + static_cast<std::size_t>(d)] = graph_->step_cost(s, d);
    cached_[static_cast<std::size_t>(s)] = 1;
  }
  return cost_[base + static_cast<std::size_t>(k)];
}

Cost DStarLite::best_rhs(int s) noexcept {
  Cost best = kInfiniteCost;
  for (int k = 0; k < kGridDirections; ++k) {
    const int w = graph_->neighbour(s, k);
    if (w >= 0) best = std::min(best, add_cost(cost(s, k), g(w)));
  }
  return best;
}

SearchKey DStarLite::key(int v) const noexcept {
  const Cost m = std::min(g(v), rhs(v));
  return {add_cost(add_cost(m, graph_->heuristic(start_, v)), km_), m};
}

SearchKey DStarLite::top_key() const noexcept {
  return queue_.empty() ? SearchKey{kInfiniteCost, kInfiniteCost} : queue_.top_key();
}

void DStarLite::update_vertex(int u) noexcept {
  if (g(u) != rhs(u)) {
    queue_.push_or_update(u, key(u));
  } else {
    queue_.remove(u);
  }
}

bool DStarLite::search_done() const noexcept {
  return !(top_key() < key(start_)) && !(rhs(start_) > g(start_));
}

SearchStatus DStarLite::step(std::int64_t max_pops) noexcept {
  if (graph_ == nullptr) return status_;
  for (std::int64_t pops = 0; pops < max_pops; ++pops) {
    if (search_done()) {
      status_ = rhs(start_) < kInfiniteCost ? SearchStatus::kReady : SearchStatus::kUnreachable;
      return status_;
    }
    const int u = queue_.top();
    const SearchKey k_old = queue_.top_key();
    const SearchKey k_new = key(u);
    ++counters_.pops;
    if (k_old < k_new) {
      queue_.push_or_update(u, k_new);
    } else if (g(u) > rhs(u)) {  // overconsistent: settle it and lower its predecessors
      ++counters_.expansions;
      g_at(u) = rhs(u);
      queue_.remove(u);
      for (int k = 0; k < kGridDirections; ++k) {
        const int s = graph_->neighbour(u, k);
        if (s < 0 || s == goal_) continue;
        rhs_at(s) = std::min(rhs(s), add_cost(cost(s, opposite(k)), g(u)));
        update_vertex(s);
      }
    } else {  // underconsistent: raise it, and whatever relied on it looks again
      ++counters_.expansions;
      const Cost g_old = g(u);
      g_at(u) = kInfiniteCost;
      for (int k = 0; k < kGridDirections; ++k) {
        const int s = graph_->neighbour(u, k);
        if (s < 0 || s == goal_) continue;
        if (rhs(s) == add_cost(cost(s, opposite(k)), g_old)) rhs_at(s) = best_rhs(s);
        update_vertex(s);
      }
      if (u != goal_) rhs_at(u) = best_rhs(u);
      update_vertex(u);
    }
  }
  status_ = search_done() ? (rhs(start_) < kInfiniteCost ? SearchStatus::kReady : SearchStatus::kUnreachable)
                          : SearchStatus::kSearching;
  return status_;
}

void DStarLite::move_start(int start) noexcept {
  if (graph_ == nullptr || start < 0 || start >= graph_->vertex_count() || start == start_) return;
  // Every queued key was computed from last_: the heuristic to the new start differs by at most
  // h(last_, start), so adding it to km keeps every queued key a lower bound.
  km_ = add_cost(km_, graph_->heuristic(last_, start));
  last_ = start;
  start_ = start;
  status_ = SearchStatus::kSearching;
}

void DStarLite::vertex_changed(int v) noexcept {
  if (graph_ == nullptr || v < 0 || v >= graph_->vertex_count()) return;
  for (int ring = -1; ring < kGridDirections; ++ring) {
    const int u = ring < 0 ? v : graph_->neighbour(v, ring);
    if (u >= 0) reread(u);
  }
  status_ = SearchStatus::kSearching;
}

void DStarLite::edges_changed(int v) noexcept {
  if (graph_ == nullptr || v < 0 || v >= graph_->vertex_count()) return;
  reread(v);
  status_ = SearchStatus::kSearching;
}

void DStarLite::reread(int u) noexcept {
  if (cached_[static_cast<std::size_t>(u)] == 0) return;  // never read: nothing relies on it
  const auto base = static_cast<std::size_t>(u) * kGridDirections;
  for (int k = 0; k < kGridDirections; ++k) {
    const Cost c_new = graph_->step_cost(u, k);
    const Cost c_old = cost_[base + static_cast<std::size_t>(k)];
    if (c_new == c_old) continue;
    ++counters_.edge_changes;
    cost_[base + static_cast<std::size_t>(k)] = c_new;
    const int w = graph_->neighbour(u, k);
    if (u != goal_ && w >= 0) {
      if (c_old > c_new) {
        rhs_at(u) = std::min(rhs(u), add_cost(c_new, g(w)));
      } else if (rhs(u) == add_cost(c_old, g(w))) {
        rhs_at(u) = best_rhs(u);
      }
    }
    update_vertex(u);
  }
}

int DStarLite::best_successor(int s) noexcept {
  Cost best = kInfiniteCost;
  int next = -1;
  for (int k = 0; k < kGridDirections; ++k) {
    const int w = graph_->neighbour(s, k);
    if (w < 0) continue;
    const Cost c = add_cost(cost(s, k), g(w));
    if (c < best) {
      best = c;
      next = w;
    }
  }
  return next;
}

int DStarLite::extract_path(std::span<int> out) noexcept {
  if (status_ != SearchStatus::kReady || out.empty()) return 0;
  int s = start_;
  std::size_t n = 0;
  out[n++] = s;
  while (s != goal_) {
    s = best_successor(s);
    if (s < 0 || n == out.size()) return 0;
    out[n++] = s;
  }
  return static_cast<int>(n);
}

int DStarLite::next_vertex() noexcept {
  if (status_ != SearchStatus::kReady) return -1;
  return start_ == goal_ ? start_ : best_successor(start_);
}

}  // namespace ringlet::planning
