#pragma once
// k-nearest-neighbour regression over experiences (Powers & Balch §IV: the learner the planner
// uses), on a nanoflann k-d tree. The prediction is the mean label of the k nearest stored
// experiences, or their mean weighted by 1 / (distance + kWeightEpsilon).
//
// Determinism. Neighbours are ranked by (squared_distance(), insertion index): among equal
// distances, which are common (every transition through empty space has the same features), the
// earlier experience wins. nanoflann decides only which points are looked at; the ranking and the
// sum are done here, in that order, with one distance function, so a prediction is the same bits
// on x86-64 and aarch64 and equal to a brute-force search's. (nanoflann itself skips a point whose
// distance equals the current k-th, and prunes with its own rounding; the result set reports a
// k-th distance slightly larger than the true one so that every tie reaches it.)
//
// Memory and the cycle. reserve() allocates the store for `capacity` experiences at start-up.
// add() copies one into the store and never allocates; it is not visible to predict() yet.
// Predictions read the published index only, and never allocate (the neighbours are kept in a
// fixed array of kMaxK). Two indexes take turns:
//
//   cycle thread:    add() ... add()                  publish() → visible from the next predict()
//   any one thread:            rebuild() (allocates, O(n log n))
//
// rebuild() builds the other index over every experience stored when it starts, while the cycle
// goes on predicting with the published one and adding; publish() swaps the two in O(1), at the
// moment the caller chooses (in lockstep: a defined frame). The cycle never waits: publish()
// returns false while no rebuilt index is ready. Only one rebuild() runs at a time, and rebuild()
// refuses (returns false) while its result waits to be published.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "ringlet/planning/speed_learner.hpp"

namespace ringlet::planning {

struct KnnParams {
  int k = 5;
  bool distance_weighted = false;
  double prior_speed = 0.0;  // m/s: the prediction while no experience is visible

  /// Empty when usable, else what is wrong (names the field).
  [[nodiscard]] std::string validate() const;
};

/// One neighbour of a query: its insertion index and squared distance.
struct Neighbour {
  std::uint32_t index = 0;
  double squared_distance = 0.0;
};

class KnnRegressor final : public SpeedLearner {
 public:
  static constexpr int kMaxK = 64;
  /// Keeps an exact match from weighing infinitely; small against the feature scale (one
  /// occupied cell of a 64-cell region is 1/64).
  static constexpr double kWeightEpsilon = 1e-3;

  /// `p` must validate().
  explicit KnnRegressor(const KnnParams& p);
  ~KnnRegressor() override;

  /// Allocates the store for `capacity` experiences (start-up); forgets every stored experience
  /// and both indexes. Not while a rebuild() runs.
  void reserve(std::size_t capacity);
  [[nodiscard]] std::size_t capacity() const noexcept { return capacity_; }
  /// Stores an experience for the next rebuild(); false (and nothing stored) when full.
  bool add(const Features& x, double speed) noexcept;
  /// Experiences stored, and those the published index holds.
  [[nodiscard]] std::size_t stored() const noexcept { return stored_.load(std::memory_order_acquire); }
  [[nodiscard]] std::size_t visible() const noexcept;

  /// Builds the unpublished index over the first `limit` stored experiences (all of them by
  /// default; allocates). False when the last rebuild is still waiting for publish(). A limit
  /// chosen by the cycle makes the index the same whenever the rebuild happens to run.
  bool rebuild(std::size_t limit = static_cast<std::size_t>(-1));
  /// Makes the last rebuild() the index predictions use; false when none is ready. O(1), no
  /// allocation, nothing freed.
  bool publish() noexcept;
  /// Whether a rebuilt index waits for publish().
  [[nodiscard]] bool pending() const noexcept { return rebuilt_ready_.load(std::memory_order_acquire); }
  /// The prediction the waiting index will give once published (the published one's while none
  /// waits): a cost model recomputes its cached costs with it before it switches. No allocation.
  [[nodiscard]] double predict_pending(const Features& x) const noexcept;

  /// reserve(max(capacity(), train.size())), add every experience, rebuild, publish.
  void fit(std::span<const Experience> train) override;
  [[nodiscard]] double predict(const Features& x) const noexcept override;
  /// The (at most k) neighbours of `x` in the published index, nearest first; returns how many
  /// were written to `out` (which needs room for k).
  std::size_t neighbours(const Features& x, std::span<Neighbour> out) const noexcept;

 private:
  struct Index;
  [[nodiscard]] std::size_t neighbours_in(const Index& index, const Features& x, std::span<Neighbour> out) const noexcept;
  [[nodiscard]] double predict_in(const Index& index, const Features& x) const noexcept;

  KnnParams params_;
  std::vector<double> points_;  // capacity × kFeatureCount, row-major; never reallocated
  std::vector<double> labels_;
  std::size_t capacity_ = 0;
  std::atomic<std::size_t> stored_{0};
  std::unique_ptr<Index> indexes_[2];
  std::atomic<int> published_{0};
  std::atomic<bool> rebuilt_ready_{false};
};

}  // namespace ringlet::planning
