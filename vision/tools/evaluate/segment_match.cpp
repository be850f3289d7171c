#include "segment_match.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace ringlet::vision::evaluate {
namespace {

double length(const Segment2& s) noexcept { return std::hypot(s.x1 - s.x0, s.y1 - s.y0); }

// Position of (x, y) along s, in pixels from its start (unclamped).
double along(const Segment2& s, double x, double y) noexcept {
  const double len = length(s);
  return len == 0.0 ? 0.0 : ((x - s.x0) * (s.x1 - s.x0) + (y - s.y0) * (s.y1 - s.y0)) / len;
}

double distance_to_segment(const Segment2& s, double x, double y) noexcept {
  const double len = length(s);
  const double t = len == 0.0 ? 0.0 : std::clamp(along(s, x, y) / len, 0.0, 1.0);
  return std::hypot(x - (s.x0 + t * (s.x1 - s.x0)), y - (s.y0 + t * (s.y1 - s.y0)));
}

double acute_angle_deg(const Segment2& a, const Segment2& b) noexcept {
  const double ta = std::atan2(a.y1 - a.y0, a.x1 - a.x0);
  const double tb = std::atan2(b.y1 - b.y0, b.x1 - b.x0);
  double d = std::fmod(std::abs(ta - tb), std::numbers::pi);
  if (d > std::numbers::pi / 2.0) d = std::numbers::pi - d;
  return d * 180.0 / std::numbers::pi;
}

// Length of the union of intervals, clipped to [0, len].
double covered(std::vector<std::pair<double, double>>& intervals, double len, double& first, double& last) {
  for (auto& [a, b] : intervals) {
    if (a > b) std::swap(a, b);
    a = std::clamp(a, 0.0, len);
    b = std::clamp(b, 0.0, len);
  }
  std::sort(intervals.begin(), intervals.end());
  double total = 0.0;
  double cur_a = 0.0;
  double cur_b = -1.0;
  first = len;
  last = 0.0;
  for (const auto& [a, b] : intervals) {
    first = std::min(first, a);
    last = std::max(last, b);
    if (a > cur_b) {
      if (cur_b >= cur_a) total += cur_b - cur_a;
      cur_a = a;
      cur_b = b;
    } else {
      cur_b = std::max(cur_b, b);
    }
  }
  if (cur_b >= cur_a) total += cur_b - cur_a;
  return total;
}

}  // namespace

MatchCounts& MatchCounts::operator+=(const MatchCounts& o) noexcept {
  detections += o.detections;
  true_positives += o.true_positives;
  truths += o.truths;
  recalled += o.recalled;
  angle_error_sum_deg += o.angle_error_sum_deg;
  endpoint_error_sum_px += o.endpoint_error_sum_px;
  extent_error_sum_px += o.extent_error_sum_px;
  return *this;
}

double MatchCounts::precision() const noexcept {
  return detections == 0 ? 0.0 : static_cast<double>(true_positives) / static_cast<double>(detections);
}
double MatchCounts::recall() const noexcept {
  return truths == 0 ? 0.0 : static_cast<double>(recalled) / static_cast<double>(truths);
}
double MatchCounts::f1() const noexcept {
  const double p = precision();
  const double r = recall();
  return p + r == 0.0 ? 0.0 : 2.0 * p * r / (p + r);
}
double MatchCounts::mean_angle_error_deg() const noexcept {
  return true_positives == 0 ? 0.0 : angle_error_sum_deg / static_cast<double>(true_positives);
}
double MatchCounts::mean_endpoint_error_px() const noexcept {
  return true_positives == 0 ? 0.0 : endpoint_error_sum_px / static_cast<double>(true_positives);
}
double MatchCounts::mean_extent_error_px() const noexcept {
  return recalled == 0 ? 0.0 : extent_error_sum_px / static_cast<double>(recalled);
}

MatchCounts match_segments(std::span<const Segment2> detected, std::span<const TruthSegment> truth,
                           const MatchParams& params) {
  MatchCounts counts;
  std::vector<std::vector<std::pair<double, double>>> cover(truth.size());
  for (const auto& d : detected) {
    // The best matching true segment: smallest mean endpoint distance among those that match.
    std::size_t best = truth.size();
    double best_distance = 0.0;
    for (std::size_t t = 0; t < truth.size(); ++t) {
      const Segment2& line = truth[t].line;
      const double e0 = distance_to_segment(line, d.x0, d.y0);
      const double e1 = distance_to_segment(line, d.x1, d.y1);
      const double tolerance = params.max_distance_px + truth[t].half_width_px;
      if (e0 > tolerance || e1 > tolerance) continue;
      if (acute_angle_deg(d, line) > params.max_angle_deg) continue;
      const double mean = (e0 + e1) / 2.0;
      if (best == truth.size() || mean < best_distance) {
        best = t;
        best_distance = mean;
      }
    }
    if (best == truth.size()) {
      ++counts.detections;  // matches nothing: a false positive
      continue;
    }
    const Segment2& t = truth[best].line;
    cover[best].emplace_back(along(t, d.x0, d.y0), along(t, d.x1, d.y1));
    if (length(t) < params.min_truth_length_px) continue;  // don't care
    ++counts.detections;
    ++counts.true_positives;
    counts.angle_error_sum_deg += acute_angle_deg(d, t);
    counts.endpoint_error_sum_px += best_distance;
  }
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const double len = length(truth[i].line);
    if (len < params.min_truth_length_px) continue;
    ++counts.truths;
    double first = 0.0;
    double last = 0.0;
    if (cover[i].empty() || covered(cover[i], len, first, last) < params.min_coverage * len) continue;
    ++counts.recalled;
    counts.extent_error_sum_px += (first + (len - last)) / 2.0;
  }
  return counts;
}

}  // namespace ringlet::vision::evaluate
