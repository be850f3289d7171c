#pragma once
// Recording experiences (Powers & Balch §III-C, §IV-A: "every time the robot achieved a waypoint
// the robot's experience was recorded"). The navigation layer tells the recorder, at each planner
// activation, which region the robot is in; when it has entered a region adjacent to the one it
// entered before, the transition between them is one experience:
//
//   features  the transition as the planner costs it, from the map at that moment
//             (RegionGraph::transition, the robot now in `to`, so `from` counts all its cells);
//   duration  from entering `from` to entering `to`;
//   achieved  the net progress speed: the straight distance between the two entry points ÷ the
//             duration. An edge's cost is the time one region of net progress takes, so detours
//             and stops (weaving between trees, waiting for Safety) must count as slowness, which
//             path length ÷ time would hide; and unlike centre distance ÷ time it stays below the
//             robot's top speed when the path only clips a region's corner. Clamped to the top
//             speed (the pose's noise over a short stay can push it a little above);
//   commanded the mean of the speeds the reactive layer commanded (MotionCommand, 0 while
//             stopped) at the activations spent in `from`.
//
// Not experiences: a jump to a region that is not adjacent (a teleport, a corner cut between two
// activations), the first region after a reset, and anything spanning a change of target (the
// leg): arriving at a goal and turning to the next is the mission's doing, not the map's.
#include <cstdint>

#include "ringlet/planning/experience.hpp"

namespace ringlet::planning {

class RegionGraph;

struct TransitionSample {
  int region = -1;          // where the robot is (−1: nowhere, e.g. no valid pose)
  double x = 0.0, y = 0.0;  // its position (m)
  std::int64_t time_ns = 0;
  std::uint64_t frame = 0;
  double commanded_speed = 0.0;  // m/s, what the reactive layer commands now
  std::uint64_t leg = 0;         // changes when the target does
};

class TransitionRecorder {
 public:
  explicit TransitionRecorder(double top_speed) noexcept : top_speed_(top_speed) {}
  /// The robot's state at one activation; true, with `out` filled, when it completes a transition.
  /// `graph` must already know the robot is in `s.region`. No allocation.
  bool observe(const RegionGraph& graph, const TransitionSample& s, Experience& out) noexcept;
  /// Forgets the region entered last (the next region entered starts afresh).
  void reset() noexcept { entered_ = false; }

 private:
  double top_speed_;
  bool entered_ = false;
  TransitionSample entry_{};     // the sample in which the current region was entered
  double commanded_sum_ = 0.0;   // over the activations spent in it
  int commanded_count_ = 0;
};

}  // namespace ringlet::planning
