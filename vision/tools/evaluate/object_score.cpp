#include "object_score.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ringlet::vision::evaluate {

ObjectCounts& ObjectCounts::operator+=(const ObjectCounts& o) noexcept {
  detections += o.detections;
  true_positives += o.true_positives;
  expected += o.expected;
  recalled += o.recalled;
  errors += o.errors;
  error_sum += o.error_sum;
  error_max = std::max(error_max, o.error_max);
  return *this;
}

double ObjectCounts::precision() const noexcept {
  return detections == 0 ? 1.0 : static_cast<double>(true_positives) / static_cast<double>(detections);
}
double ObjectCounts::recall() const noexcept {
  return expected == 0 ? 1.0 : static_cast<double>(recalled) / static_cast<double>(expected);
}
double ObjectCounts::f1() const noexcept {
  const double p = precision(), r = recall();
  return p + r > 0.0 ? 2.0 * p * r / (p + r) : 0.0;
}
double ObjectCounts::mean_error() const noexcept {
  return errors == 0 ? 0.0 : error_sum / static_cast<double>(errors);
}

namespace {

struct Pair {
  double image_distance;
  std::size_t found;
  std::size_t truth;
};

/// Greedy one-to-one assignment of the admissible pairs, nearest first (ties by index: deterministic).
std::vector<Pair> assign(std::vector<Pair> pairs, std::size_t n_found, std::size_t n_truth) {
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    if (a.image_distance != b.image_distance) return a.image_distance < b.image_distance;
    return a.found != b.found ? a.found < b.found : a.truth < b.truth;
  });
  std::vector<bool> found_used(n_found), truth_used(n_truth);
  std::vector<Pair> out;
  for (const Pair& p : pairs) {
    if (found_used[p.found] || truth_used[p.truth]) continue;
    found_used[p.found] = truth_used[p.truth] = true;
    out.push_back(p);
  }
  return out;
}

double relative_error(double detected, double truth) { return std::abs(detected - truth) / truth; }

void add_error(ObjectCounts& c, double detected, double truth) {
  if (!(truth > 0.0)) return;
  const double e = relative_error(detected, truth);
  ++c.errors;
  c.error_sum += e;
  c.error_max = std::max(c.error_max, e);
}

double iou(const FoundRobot& d, const TruthRobot& t) {
  const double w = std::min(d.left + d.width, t.u1) - std::max(d.left, t.u0);
  const double h = std::min(d.top + d.height, t.v1) - std::max(d.top, t.v0);
  if (w <= 0.0 || h <= 0.0) return 0.0;
  const double inter = w * h;
  const double uni = d.width * d.height + (t.u1 - t.u0) * (t.v1 - t.v0) - inter;
  return uni > 0.0 ? inter / uni : 0.0;
}

}  // namespace

ObjectCounts score_balls(std::span<const FoundBall> found, std::span<const TruthBall> truth, const BallMatchParams& p) {
  ObjectCounts c;
  c.detections = found.size();
  const auto expected = [&](const TruthBall& t) {
    return t.in_front && t.visible && t.distance_m <= p.max_distance_m &&
           t.in_image_fraction * t.visible_fraction >= p.min_visible;
  };
  std::vector<Pair> pairs;
  for (std::size_t i = 0; i < found.size(); ++i) {
    for (std::size_t j = 0; j < truth.size(); ++j) {
      const TruthBall& t = truth[j];
      if (!t.in_front || !t.visible) continue;
      const double d = std::hypot(found[i].u - t.u, found[i].v - t.v);
      if (d <= std::max(p.centre_share * t.radius_px, p.min_centre_px)) pairs.push_back({d, i, j});
    }
  }
  for (const TruthBall& t : truth) c.expected += expected(t) ? 1U : 0U;
  for (const Pair& m : assign(std::move(pairs), found.size(), truth.size())) {
    ++c.true_positives;
    if (!expected(truth[m.truth])) continue;
    ++c.recalled;
    if (found[m.found].ground_valid) add_error(c, found[m.found].distance_m, truth[m.truth].distance_m);
  }
  return c;
}

ObjectCounts score_robots(std::span<const FoundRobot> found, std::span<const TruthRobot> truth, int width, int height,
                          const RobotMatchParams& p, std::vector<RobotMatch>* matches) {
  ObjectCounts c;
  c.detections = found.size();
  const auto expected = [&](const TruthRobot& t) {
    return t.in_front && t.visible && t.foot_projects && t.distance_m <= p.max_distance_m &&
           t.visible_fraction >= p.min_visible && t.foot_u >= 0.0 && t.foot_u < width && t.foot_v >= 0.0 &&
           t.foot_v < height;
  };
  const auto foot_tolerance = [&](const TruthRobot& t) {
    return std::max(p.foot_share * (t.has_box ? t.u1 - t.u0 : 0.0), p.min_foot_px);
  };
  std::vector<Pair> pairs;
  for (std::size_t i = 0; i < found.size(); ++i) {
    for (std::size_t j = 0; j < truth.size(); ++j) {
      const TruthRobot& t = truth[j];
      if (!t.in_front || !t.visible) continue;
      const double d =
          t.foot_projects ? std::hypot(found[i].foot_u - t.foot_u, found[i].foot_v - t.foot_v) : std::numeric_limits<double>::infinity();
      if (d <= foot_tolerance(t) || (t.has_box && iou(found[i], t) >= p.min_iou)) {
        pairs.push_back({std::isfinite(d) ? d : 1e9, i, j});
      }
    }
  }
  for (const TruthRobot& t : truth) c.expected += expected(t) ? 1U : 0U;
  for (const Pair& m : assign(std::move(pairs), found.size(), truth.size())) {
    ++c.true_positives;
    if (!expected(truth[m.truth])) continue;
    ++c.recalled;
    add_error(c, found[m.found].distance_m, truth[m.truth].distance_m);
    if (matches != nullptr) {
      const TruthRobot& t = truth[m.truth];
      matches->push_back({t.distance_m, found[m.found].distance_m, relative_error(found[m.found].distance_m, t.distance_m),
                          m.image_distance, m.image_distance <= foot_tolerance(t)});
    }
  }
  return c;
}

}  // namespace ringlet::vision::evaluate
