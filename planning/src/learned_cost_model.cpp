#include "ringlet/planning/learned_cost_model.hpp"

#include <algorithm>
#include <cmath>

#include "ringlet/planning/experience.hpp"
#include "ringlet/planning/region_graph.hpp"

namespace ringlet::planning {

std::string LearnedCostParams::validate() const {
  if (!(top_speed > 0.0) || !std::isfinite(top_speed)) return "top_speed must be a positive speed in m/s";
  if (wall_occupied < 0) return "wall_occupied must not be negative";
  if (memo_capacity < 1) return "memo_capacity must be at least 1";
  return {};
}

LearnedCostModel::LearnedCostModel(KnnRegressor& knn, const LearnedCostParams& p, const MapConfig& map)
    : knn_(knn), params_(p), regions_x_(map.regions_x()), regions_y_(map.regions_y()) {
  const auto edges = static_cast<std::size_t>(regions_x_) * static_cast<std::size_t>(regions_y_) * kGridDirections;
  speed_.assign(edges, 0.0);
  next_.assign(edges, 0.0);
  state_.assign(edges, 0);
  memo_.reserve(p.memo_capacity);
  next_memo_.reserve(p.memo_capacity);
  changed_.assign(edges / kGridDirections, -1);
}

double LearnedCostModel::clamp(double s) const noexcept {
  return std::isfinite(s) ? std::clamp(s, 0.0, params_.top_speed) : 0.0;  // NaN: impassable
}

double LearnedCostModel::expected_speed(const RegionTransition& t) const noexcept {
  if (t.from_occupied > params_.wall_occupied || t.to_occupied > params_.wall_occupied) return 0.0;
  const std::size_t e = static_cast<std::size_t>(t.from) * kGridDirections + static_cast<std::size_t>(t.direction);
  if ((state_[e] & kValid) != 0) return speed_[e];
  const Features x = transition_features(t);
  double s = 0.0;
  if (!memo_.find(x, s)) {
    s = clamp(knn_.predict(x));
    ++predictions_;
    memo_.insert(x, s);
  }
  speed_[e] = s;
  state_[e] = kValid;
  return s;
}

std::size_t LearnedCostModel::region_changed(int region, std::span<int> sources) noexcept {
  const int rx = region % regions_x_, ry = region / regions_x_;
  std::size_t n = 0;
  for (int k = 0; k < kGridDirections; ++k) {
    for (int slot = kFrom; slot < kFeatureCount; ++slot) {
      // The edge (v, k) whose slot lands on `region`: v = region - offset.
      const RegionOffset o = feature_offset(k, slot);
      const int vx = rx - o.dx, vy = ry - o.dy;
      if (vx < 0 || vy < 0 || vx >= regions_x_ || vy >= regions_y_) continue;
      const int v = vy * regions_x_ + vx;
      forget(static_cast<std::size_t>(v) * kGridDirections + static_cast<std::size_t>(k));
      if (std::find(sources.begin(), sources.begin() + static_cast<std::ptrdiff_t>(n), v) ==
              sources.begin() + static_cast<std::ptrdiff_t>(n) &&
          n < sources.size()) {
        sources[n++] = v;
      }
    }
  }
  return n;
}

void LearnedCostModel::edges_from_changed(int v) noexcept {
  if (v < 0 || v >= regions_x_ * regions_y_) return;
  for (int k = 0; k < kGridDirections; ++k) forget(static_cast<std::size_t>(v) * kGridDirections + static_cast<std::size_t>(k));
}

bool LearnedCostModel::begin_refresh() noexcept {
  if (refreshing_ || !knn_.pending()) return false;
  refreshing_ = true;
  cursor_ = 0;
  next_memo_.clear();
  return true;
}

bool LearnedCostModel::refresh(const RegionGraph& graph, std::int64_t max_predictions, std::int64_t max_edges) noexcept {
  if (!refreshing_) return true;
  std::int64_t predicted = 0, visited = 0;
  while (cursor_ < state_.size() && predicted < max_predictions && visited < max_edges) {
    const std::size_t e = cursor_++;
    if ((state_[e] & kValid) == 0) continue;  // never asked for, or forgotten: computed when asked
    ++visited;
    const Features x = transition_features(graph.transition(static_cast<int>(e / kGridDirections),
                                                            static_cast<int>(e % kGridDirections)));
    double s = 0.0;
    if (!next_memo_.find(x, s)) {
      s = clamp(knn_.predict_pending(x));
      ++predictions_;
      ++predicted;
      next_memo_.insert(x, s);
    }
    next_[e] = s;
    state_[e] |= kNext;
  }
  refresh_edges_ += static_cast<std::uint64_t>(visited);
  return cursor_ == state_.size();
}

std::span<const int> LearnedCostModel::finish_refresh() noexcept {
  if (!refreshing_) return {};
  (void)knn_.publish();
  memo_.swap(next_memo_);
  next_memo_.clear();
  std::size_t n = 0;
  const std::size_t vertices = state_.size() / kGridDirections;
  for (std::size_t v = 0; v < vertices; ++v) {
    bool changed = false;
    for (std::size_t e = v * kGridDirections; e < (v + 1) * kGridDirections; ++e) {
      if ((state_[e] & kNext) != 0) {
        changed = changed || next_[e] != speed_[e];
        speed_[e] = next_[e];
        state_[e] = kValid;
      } else if ((state_[e] & kValid) != 0) {
        // Computed with the old index after the refresh had passed it: ask again when needed.
        forget(e);
        changed = true;
      }
    }
    if (changed) changed_[n++] = static_cast<int>(v);
  }
  refreshing_ = false;
  return {changed_.data(), n};
}

}  // namespace ringlet::planning
