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

std::size_t width_bucket(double half_width_px) noexcept {
  std::size_t b = 0;
  while (b + 1 < kWidthBucketsPx.size() && 2.0 * half_width_px >= kWidthBucketsPx[b + 1]) ++b;
  return b;
}

MatchCounts& MatchCounts::operator+=(const MatchCounts& o) noexcept {
  detections += o.detections;
  true_positives += o.true_positives;
  truths += o.truths;
  recalled += o.recalled;
  angle_error_sum_deg += o.angle_error_sum_deg;
  endpoint_error_sum_px += o.endpoint_error_sum_px;
  extent_error_sum_px += o.extent_error_sum_px;
  for (std::size_t b = 0; b < kWidthBucketsPx.size(); ++b) {
    truths_by_width[b] += o.truths_by_width[b];
    recalled_by_width[b] += o.recalled_by_width[b];
  }
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
  // The markings: pieces of one painted line, and the visible extent they span.
  struct Marking {
    Segment2 extent{};
    double half_width_px = 0.0;
    bool cares = false;  // some piece is long enough to be scored
    std::vector<std::size_t> pieces;
  };
  std::vector<Marking> markings;
  std::vector<int> marking_ids;
  for (std::size_t t = 0; t < truth.size(); ++t) {
    const int id = truth[t].marking;
    std::size_t m = markings.size();
    if (id >= 0) {
      const auto it = std::find(marking_ids.begin(), marking_ids.end(), id);
      if (it != marking_ids.end()) m = static_cast<std::size_t>(it - marking_ids.begin());
    }
    if (m == markings.size()) {
      markings.emplace_back();
      marking_ids.push_back(id);
    }
    markings[m].pieces.push_back(t);
    markings[m].half_width_px = std::max(markings[m].half_width_px, truth[t].half_width_px);
    markings[m].cares = markings[m].cares || length(truth[t].line) >= params.min_truth_length_px;
  }
  for (Marking& m : markings) {
    // The two farthest-apart piece ends.
    std::vector<std::pair<double, double>> ends;
    for (const std::size_t t : m.pieces) {
      ends.emplace_back(truth[t].line.x0, truth[t].line.y0);
      ends.emplace_back(truth[t].line.x1, truth[t].line.y1);
    }
    double widest = -1.0;
    for (std::size_t i = 0; i < ends.size(); ++i) {
      for (std::size_t j = i + 1; j < ends.size(); ++j) {
        const double d = std::hypot(ends[i].first - ends[j].first, ends[i].second - ends[j].second);
        if (d > widest) {
          widest = d;
          m.extent = {ends[i].first, ends[i].second, ends[j].first, ends[j].second};
        }
      }
    }
  }

  MatchCounts counts;
  std::vector<std::vector<std::pair<double, double>>> cover(truth.size());
  for (const auto& d : detected) {
    // The best matching marking: smallest mean endpoint distance among those that match.
    std::size_t best = markings.size();
    double best_distance = 0.0;
    for (std::size_t m = 0; m < markings.size(); ++m) {
      const Segment2& line = markings[m].extent;
      const double e0 = distance_to_segment(line, d.x0, d.y0);
      const double e1 = distance_to_segment(line, d.x1, d.y1);
      const double tolerance = params.max_distance_px + markings[m].half_width_px;
      if (e0 > tolerance || e1 > tolerance) continue;
      if (acute_angle_deg(d, line) > params.max_angle_deg) continue;
      const double mean = (e0 + e1) / 2.0;
      if (best == markings.size() || mean < best_distance) {
        best = m;
        best_distance = mean;
      }
    }
    if (best == markings.size()) {
      ++counts.detections;  // matches nothing: a false positive
      continue;
    }
    for (const std::size_t t : markings[best].pieces) {
      const Segment2& piece = truth[t].line;
      cover[t].emplace_back(along(piece, d.x0, d.y0), along(piece, d.x1, d.y1));
    }
    if (!markings[best].cares) continue;  // don't care
    ++counts.detections;
    ++counts.true_positives;
    counts.angle_error_sum_deg += acute_angle_deg(d, markings[best].extent);
    counts.endpoint_error_sum_px += best_distance;
  }
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const double len = length(truth[i].line);
    if (len < params.min_truth_length_px) continue;
    ++counts.truths;
    const std::size_t bucket = width_bucket(truth[i].half_width_px);
    ++counts.truths_by_width[bucket];
    double first = 0.0;
    double last = 0.0;
    if (cover[i].empty() || covered(cover[i], len, first, last) < params.min_coverage * len) continue;
    ++counts.recalled;
    ++counts.recalled_by_width[bucket];
    counts.extent_error_sum_px += (first + (len - last)) / 2.0;
  }
  return counts;
}

}  // namespace ringlet::vision::evaluate
