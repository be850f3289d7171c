#pragma once
// One learning experience of Powers & Balch (§III-C, eq. 22): Exp = (g, M_local), the control law
// (drive from region r° to the next region of the plan) and the local map around it, labelled
// with the measured average speed m_c. The learners regress speed on these features.
//
// The features are encoded in the robot's frame ("forward", "left"), not the map's ("north"):
// the paper's symmetry argument. The frame is chosen from the grid direction k of the transition:
// straight moves (k even) are rotated so that travel runs along +x, diagonal ones (k odd) along
// +x+y. Both rotations are by a multiple of 90°, which maps the region grid onto itself, so the
// same local situation turned by 90°, 180° or 270° gives bit-identical features. (A 45° turn does
// not map the grid onto itself: straight and diagonal moves are two kinds, told apart by the
// `kDiagonal` feature.) The features keep left and right apart (a reactive layer is not always
// symmetric, and the data decides); a mirrored situation gives the same features with the left
// and right slots swapped (`mirrored()`).
//
// Each region slot holds the fraction of the region's cells that are occupied, in [0, 1]: the
// same scale for every map resolution and region size, and the [0, 1] range Weka's IBk normalises
// attributes to (the paper's kNN), so no slot outweighs another in the distance. A region off the
// map counts as full (the robot cannot drive there). `from` and `to` take the transition's own
// counts, so the robot's region reads as empty when left, as the cost model sees it.
//
// Slots, as region offsets (x, y) from `from` in the travel frame (before the rotation back to
// the map; left is the +y side of a straight move along +x, the −x+y side of a diagonal one):
//
// | slot          | straight (travel +x) | diagonal (travel +x+y) | why |
// |---------------|----------------------|------------------------|-----|
// | diagonal      | 0                    | 1                      | a diagonal step is √2 longer and passes a corner |
// | from, to      | (0,0), (1,0)         | (0,0), (1,1)           | the regions driven through: the baseline's rule |
// | from_left/right | (0,±1)             | (−1,1), (1,−1)         | the corridor's width beside the start |
// | to_left/right | (1,±1)               | (0,2), (2,0)           | the corridor's width beside the end |
// | behind        | (−1,0)               | (−1,−1)                | room to arrive from straight behind |
// | ahead         | (2,0)                | (2,2)                  | what the robot faces on arrival: a wall ahead slows it (Maintain Headway) |
// | corner_left/right | (2,1), (2,−1)    | (0,1), (1,0)           | diagonal: the two regions sharing the corner the path crosses (the tight spot); straight: the regions diagonally ahead, where the path bends next |
//
// The goal is deliberately not a feature: an edge's cost must depend on
// the edge and the map only, or D* Lite's incremental repair is wrong when the goal moves.
#include <array>
#include <cstdint>
#include <string_view>

#include "ringlet/planning/cost_model.hpp"

namespace ringlet::planning {

enum FeatureIndex : int {
  kDiagonal = 0,
  kFrom,
  kTo,
  kFromLeft,
  kFromRight,
  kToLeft,
  kToRight,
  kBehind,
  kAhead,
  kCornerLeft,
  kCornerRight,
  kFeatureCount
};

using Features = std::array<double, kFeatureCount>;

/// The slots' names, as in the experience file's column header.
inline constexpr std::array<std::string_view, kFeatureCount> kFeatureNames{
    "diagonal", "from", "to", "from_left", "from_right", "to_left", "to_right",
    "behind", "ahead", "corner_left", "corner_right"};

/// The features of transition `t` (its map must be set; `to` on the grid). No allocation.
[[nodiscard]] Features transition_features(const RegionTransition& t) noexcept;

/// Where feature slot `slot` (kFrom ... kCornerRight) of a transition in grid direction
/// `direction` looks, as a region offset (dx, dy) from `from` in the map's frame: the region whose
/// count the slot reads. A cache of predictions uses it to find every edge a changed region feeds.
struct RegionOffset {
  int dx = 0, dy = 0;
};
[[nodiscard]] RegionOffset feature_offset(int direction, int slot) noexcept;

/// The features of the mirror image of the situation (reflected across the travel axis): every
/// left slot swapped with its right slot.
[[nodiscard]] Features mirrored(const Features& x) noexcept;

/// Squared Euclidean distance, summed in slot order: the one definition the kNN learner orders
/// neighbours by (so a brute-force check can reproduce it bit for bit).
[[nodiscard]] inline double squared_distance(const Features& a, const Features& b) noexcept {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double d = a[i] - b[i];
    sum += d * d;
  }
  return sum;
}

/// One recorded transition: what the planner expected and what the reactive layer achieved.
struct Experience {
  Features features{};
  double commanded_speed = 0.0;  // m/s: the mean speed the reactive layer commanded over the transition
  double achieved_speed = 0.0;   // m/s: m_c, the average speed over the transition (the label)
  double duration_s = 0.0;       // s from entering `from` to entering `to`
  std::uint64_t frame = 0;       // the executive's frame in which `to` was entered
  std::int64_t time_ns = 0;      // the robot's time at that frame

  friend bool operator==(const Experience&, const Experience&) = default;
};

}  // namespace ringlet::planning
