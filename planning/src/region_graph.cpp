#include "ringlet/planning/region_graph.hpp"

#include <algorithm>
#include <cmath>

namespace ringlet::planning {

std::string BinaryCostModel::Params::validate() const {
  if (max_occupied < 0) return "max_occupied must not be negative";
  if (!(top_speed > 0.0) || !std::isfinite(top_speed)) return "top_speed must be a positive speed in m/s";
  return {};
}

RegionTransition RegionGraph::transition(int v, int k) const noexcept {
  RegionTransition t;
  t.from = v;
  t.to = neighbour(v, k);
  t.from_occupied = v == robot_region_ ? 0 : map_.region_count(v);
  t.to_occupied = t.to < 0 ? 0 : map_.region_count(t.to);
  t.direction = k;
  t.distance = map_.config().region_size() * (is_diagonal(k) ? kSqrt2 : 1.0);
  t.map = &map_;
  return t;
}

double RegionGraph::speed(int v, int k) const noexcept {
  const RegionTransition t = transition(v, k);
  if (t.to < 0) return 0.0;
  const double s = model_.expected_speed(t);
  return std::isfinite(s) && s > 0.0 ? std::min(s, model_.top_speed()) : 0.0;  // NaN: impassable
}

Cost RegionGraph::min_step_cost() const noexcept {
  return std::max<Cost>(1, static_cast<Cost>(std::floor(map_.config().region_size() / model_.top_speed() * kCostPerSecond)));
}

Cost RegionGraph::step_cost(int v, int k) const noexcept {
  const double s = speed(v, k);
  if (s <= 0.0) return kInfiniteCost;
  if (is_diagonal(k) && (speed(v, (k + 1) % kGridDirections) <= 0.0 || speed(v, (k + 7) % kGridDirections) <= 0.0))
    return kInfiniteCost;
  const double seconds = map_.config().region_size() * (is_diagonal(k) ? kSqrt2 : 1.0) / s;
  if (!(seconds * kCostPerSecond < static_cast<double>(kInfiniteCost / 4))) return kInfiniteCost;  // a crawl: as good as none
  // Never below the heuristic's weights, whatever the rounding: the heuristic stays consistent.
  const Cost bound = is_diagonal(k) ? min_diagonal_cost() : min_step_cost();
  return std::max(bound, static_cast<Cost>(std::llround(seconds * kCostPerSecond)));
}

}  // namespace ringlet::planning
