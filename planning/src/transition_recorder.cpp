#include "ringlet/planning/transition_recorder.hpp"

#include <algorithm>
#include <cmath>

#include "ringlet/hal/portable_math.hpp"
#include "ringlet/planning/region_graph.hpp"

namespace ringlet::planning {
namespace {

/// The direction from region a to region b when they are 8-adjacent, else −1.
int direction_between(const GridGraph& g, int a, int b) noexcept {
  for (int k = 0; k < kGridDirections; ++k) {
    if (g.neighbour(a, k) == b) return k;
  }
  return -1;
}

}  // namespace

bool TransitionRecorder::observe(const RegionGraph& graph, const TransitionSample& s, Experience& out) noexcept {
  if (s.region < 0) {
    entered_ = false;
    return false;
  }
  if (entered_ && s.leg == entry_.leg && s.region == entry_.region) {
    commanded_sum_ += s.commanded_speed;
    ++commanded_count_;
    return false;
  }
  bool recorded = false;
  const int k = entered_ && s.leg == entry_.leg ? direction_between(graph, entry_.region, s.region) : -1;
  if (k >= 0 && s.time_ns > entry_.time_ns) {
    const RegionTransition t = graph.transition(entry_.region, k);
    out.features = transition_features(t);
    out.duration_s = static_cast<double>(s.time_ns - entry_.time_ns) * 1e-9;
    out.achieved_speed = std::min(hal::portable_hypot(s.x - entry_.x, s.y - entry_.y) / out.duration_s, top_speed_);
    out.commanded_speed = commanded_sum_ / commanded_count_;  // at least the entry's sample
    out.frame = s.frame;
    out.time_ns = s.time_ns;
    recorded = true;
  }
  entered_ = true;
  entry_ = s;
  commanded_sum_ = s.commanded_speed;
  commanded_count_ = 1;
  return recorded;
}

}  // namespace ringlet::planning
