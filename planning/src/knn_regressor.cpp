#include "ringlet/planning/knn_regressor.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <nanoflann.hpp>

namespace ringlet::planning {
namespace {

/// nanoflann's view of the first `count` stored experiences.
struct PointCloud {
  const double* points = nullptr;
  std::size_t count = 0;

  [[nodiscard]] std::size_t kdtree_get_point_count() const noexcept { return count; }
  [[nodiscard]] double kdtree_get_pt(std::uint32_t i, std::size_t dim) const noexcept {
    return points[static_cast<std::size_t>(i) * kFeatureCount + dim];
  }
  template <class BoundingBox>
  bool kdtree_get_bbox(BoundingBox&) const noexcept {
    return false;  // let nanoflann compute it
  }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>, PointCloud,
                                                 kFeatureCount, std::uint32_t>;

/// The k best by (distance, insertion index), whatever order nanoflann offers points in. Distances
/// are recomputed with squared_distance(): nanoflann's own (summed in another order) only decides
/// which points are offered, and worstDist() leaves it a margin so that no tie or rounding
/// difference keeps a point away.
class RankedNeighbours {
 public:
  using DistanceType = double;

  RankedNeighbours(std::span<Neighbour> slots, const Features& query, const PointCloud& cloud) noexcept
      : slots_(slots), query_(query), cloud_(cloud) {}

  [[nodiscard]] std::size_t size() const noexcept { return count_; }
  [[nodiscard]] bool full() const noexcept { return count_ == slots_.size(); }

  bool addPoint(double, std::uint32_t index) noexcept {
    Features p;
    std::copy_n(cloud_.points + static_cast<std::size_t>(index) * kFeatureCount, kFeatureCount, p.begin());
    const Neighbour n{index, squared_distance(query_, p)};
    if (full() && !before(n, slots_[count_ - 1])) return true;
    std::size_t i = full() ? count_ - 1 : count_++;
    for (; i > 0 && before(n, slots_[i - 1]); --i) slots_[i] = slots_[i - 1];
    slots_[i] = n;
    return true;  // keep searching
  }

  /// The search radius nanoflann prunes with: the k-th distance plus a relative margin far above
  /// its rounding (~1e-16) and far below any real gap between distances.
  [[nodiscard]] double worstDist() const noexcept {
    if (!full()) return std::numeric_limits<double>::max();
    const double worst = slots_[count_ - 1].squared_distance;
    return std::max(worst * (1.0 + 1e-9), std::nextafter(worst, std::numeric_limits<double>::infinity()));
  }

 private:
  static bool before(const Neighbour& a, const Neighbour& b) noexcept {
    return a.squared_distance < b.squared_distance || (a.squared_distance == b.squared_distance && a.index < b.index);
  }

  std::span<Neighbour> slots_;
  const Features& query_;
  const PointCloud& cloud_;
  std::size_t count_ = 0;
};

}  // namespace

struct KnnRegressor::Index {
  PointCloud cloud;
  std::unique_ptr<Tree> tree;  // null while empty
};

std::string KnnParams::validate() const {
  if (k < 1 || k > KnnRegressor::kMaxK) return "k must be 1 to " + std::to_string(KnnRegressor::kMaxK);
  if (!std::isfinite(prior_speed) || prior_speed < 0.0) return "prior_speed must be a speed in m/s, not negative";
  return {};
}

KnnRegressor::KnnRegressor(const KnnParams& p) : params_(p) {
  indexes_[0] = std::make_unique<Index>();
  indexes_[1] = std::make_unique<Index>();
}

KnnRegressor::~KnnRegressor() = default;

void KnnRegressor::reserve(std::size_t capacity) {
  for (auto& index : indexes_) *index = Index{};
  points_.assign(capacity * kFeatureCount, 0.0);
  labels_.assign(capacity, 0.0);
  capacity_ = capacity;
  stored_.store(0, std::memory_order_release);
  published_.store(0, std::memory_order_release);
  rebuilt_ready_.store(false, std::memory_order_release);
}

bool KnnRegressor::add(const Features& x, double speed) noexcept {
  const std::size_t n = stored_.load(std::memory_order_relaxed);  // only this thread writes it
  if (n >= capacity_) return false;
  std::copy(x.begin(), x.end(), points_.begin() + static_cast<std::ptrdiff_t>(n * kFeatureCount));
  labels_[n] = speed;
  stored_.store(n + 1, std::memory_order_release);  // the point is complete before it counts
  return true;
}

std::size_t KnnRegressor::visible() const noexcept {
  return indexes_[published_.load(std::memory_order_acquire)]->cloud.count;
}

bool KnnRegressor::rebuild(std::size_t limit) {
  if (rebuilt_ready_.load(std::memory_order_acquire)) return false;
  Index& back = *indexes_[1 - published_.load(std::memory_order_acquire)];
  back.cloud = PointCloud{points_.data(), std::min(limit, stored())};
  back.tree.reset();
  if (back.cloud.count > 0)
    back.tree = std::make_unique<Tree>(kFeatureCount, back.cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  rebuilt_ready_.store(true, std::memory_order_release);
  return true;
}

bool KnnRegressor::publish() noexcept {
  if (!rebuilt_ready_.load(std::memory_order_acquire)) return false;
  published_.store(1 - published_.load(std::memory_order_relaxed), std::memory_order_release);
  rebuilt_ready_.store(false, std::memory_order_release);
  return true;
}

void KnnRegressor::fit(std::span<const Experience> train) {
  reserve(std::max(capacity_, train.size()));
  for (const Experience& e : train) (void)add(e.features, e.achieved_speed);
  (void)rebuild();
  (void)publish();
}

std::size_t KnnRegressor::neighbours(const Features& x, std::span<Neighbour> out) const noexcept {
  return neighbours_in(*indexes_[published_.load(std::memory_order_acquire)], x, out);
}

std::size_t KnnRegressor::neighbours_in(const Index& index, const Features& x, std::span<Neighbour> out) const noexcept {
  const std::size_t k = std::min({static_cast<std::size_t>(params_.k), out.size(), index.cloud.count});
  if (k == 0 || !index.tree) return 0;
  RankedNeighbours result(out.first(k), x, index.cloud);
  // findNeighbors throws only for an index that was never built: ours is built whenever it holds
  // a point.
  index.tree->findNeighbors(result, x.data(), nanoflann::SearchParams());
  return result.size();
}

double KnnRegressor::predict(const Features& x) const noexcept {
  return predict_in(*indexes_[published_.load(std::memory_order_acquire)], x);
}

double KnnRegressor::predict_pending(const Features& x) const noexcept {
  const int published = published_.load(std::memory_order_acquire);
  return predict_in(*indexes_[pending() ? 1 - published : published], x);
}

double KnnRegressor::predict_in(const Index& index, const Features& x) const noexcept {
  std::array<Neighbour, kMaxK> found{};
  const std::size_t n = neighbours_in(index, x, found);
  if (n == 0) return params_.prior_speed;
  double sum = 0.0, weights = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = params_.distance_weighted ? 1.0 / (std::sqrt(found[i].squared_distance) + kWeightEpsilon) : 1.0;
    sum += w * labels_[found[i].index];
    weights += w;
  }
  return sum / weights;
}

}  // namespace ringlet::planning
