#include "circle_score.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "dataset_frame.hpp"

namespace ringlet::vision::evaluate {
namespace {

double distance_to_segment(const Segment2& s, double x, double y) noexcept {
  const double dx = s.x1 - s.x0, dy = s.y1 - s.y0;
  const double len2 = dx * dx + dy * dy;
  const double t = len2 == 0.0 ? 0.0 : std::clamp(((x - s.x0) * dx + (y - s.y0) * dy) / len2, 0.0, 1.0);
  return std::hypot(x - (s.x0 + t * dx), y - (s.y0 + t * dy));
}

}  // namespace

CircleCounts& CircleCounts::operator+=(const CircleCounts& o) noexcept {
  detections += o.detections;
  true_positives += o.true_positives;
  truths += o.truths;
  recalled += o.recalled;
  centre_error_sum_m += o.centre_error_sum_m;
  radius_error_sum_m += o.radius_error_sum_m;
  for (std::size_t b = 0; b < kRingDistanceBinsM.size(); ++b) {
    truths_by_distance[b] += o.truths_by_distance[b];
    recalled_by_distance[b] += o.recalled_by_distance[b];
  }
  return *this;
}

std::size_t ring_distance_bin(const hal::RobotPoint& centre) noexcept {
  const double d = std::hypot(centre.x, centre.y);
  std::size_t bin = 0;
  while (bin + 1 < kRingDistanceBinsM.size() && d >= kRingDistanceBinsM[bin + 1]) ++bin;
  return bin;
}
double CircleCounts::precision() const noexcept {
  return detections == 0 ? 0.0 : static_cast<double>(true_positives) / static_cast<double>(detections);
}
double CircleCounts::recall() const noexcept {
  return truths == 0 ? 0.0 : static_cast<double>(recalled) / static_cast<double>(truths);
}
double CircleCounts::f1() const noexcept {
  const double p = precision(), r = recall();
  return p + r == 0.0 ? 0.0 : 2.0 * p * r / (p + r);
}
double CircleCounts::mean_centre_error_m() const noexcept {
  return true_positives == 0 ? 0.0 : centre_error_sum_m / static_cast<double>(true_positives);
}
double CircleCounts::mean_radius_error_m() const noexcept {
  return true_positives == 0 ? 0.0 : radius_error_sum_m / static_cast<double>(true_positives);
}

CircleCounts score_circle(const DetectedCircle& detected, std::span<const TruthRing> rings, const CircleMatchParams& p) {
  CircleCounts c;
  bool matched_expected = false, matched_any = false;
  std::size_t matched_bin = 0;
  double centre_error = 0.0, radius_error = 0.0;
  for (const TruthRing& ring : rings) {
    const bool expected = ring.visible && ring.visible_fraction * 360.0 >= p.min_visible_deg;
    if (expected) {
      ++c.truths;
      ++c.truths_by_distance[ring_distance_bin(ring.centre)];
    }
    if (!detected.seen || !ring.visible) continue;
    const double ce = std::hypot(detected.centre.x - ring.centre.x, detected.centre.y - ring.centre.y);
    const double re = std::abs(detected.radius - ring.radius);
    if (ce <= p.max_centre_error_m && re <= p.max_radius_error_m) {
      if (!matched_any || ce < centre_error) {
        centre_error = ce;
        radius_error = re;
      }
      matched_any = true;
      if (expected && !matched_expected) matched_bin = ring_distance_bin(ring.centre);
      matched_expected |= expected;
    }
  }
  if (matched_expected) {
    ++c.recalled;
    ++c.recalled_by_distance[matched_bin];
  }
  if (detected.seen) {
    // A detection matching only a don't-care ring is left out, as for line segments.
    const bool dont_care = matched_any && !matched_expected;
    if (!dont_care) {
      ++c.detections;
      if (matched_any) {
        ++c.true_positives;
        c.centre_error_sum_m += centre_error;
        c.radius_error_sum_m += radius_error;
      }
    }
  }
  return c;
}

RingImage project_ring(const TruthRing& ring, const hal::CameraIntrinsics& k, const hal::CameraPose& pose) {
  RingImage out;
  constexpr int kSamples = 720;
  // Only the part in and near the picture: samples far outside it (behind the camera, beside it)
  // project to wild places, and a piece joining two of them would cross the image.
  constexpr double kMargin = 50.0;
  const auto near_image = [&](const hal::Pixel& p) {
    return p.u >= -kMargin && p.u <= k.width + kMargin && p.v >= -kMargin && p.v <= k.height + kMargin;
  };
  std::optional<hal::Pixel> previous;
  for (int i = 0; i <= kSamples; ++i) {
    const double a = 2.0 * std::numbers::pi * i / kSamples;
    const hal::RobotPoint g{ring.centre.x + ring.radius * std::cos(a), ring.centre.y + ring.radius * std::sin(a)};
    auto px = hal::project(k, pose, {g.x, g.y, 0.0});
    if (px && !near_image(*px)) px.reset();
    if (px && previous) {
      out.pieces.push_back({previous->u, previous->v, px->u, px->v});
      // The paint runs along the tangent (−sin a, cos a).
      out.half_width_px.push_back(projected_half_width(k, pose, g, -std::sin(a), std::cos(a), ring.width));
    }
    previous = px;
  }
  return out;
}

bool lies_on_ring(const Segment2& s, const RingImage& ring, double max_distance_px) {
  if (ring.pieces.empty()) return false;
  for (int i = 0; i <= 4; ++i) {
    const double t = i / 4.0;
    const double x = s.x0 + t * (s.x1 - s.x0), y = s.y0 + t * (s.y1 - s.y0);
    bool near = false;
    for (std::size_t p = 0; p < ring.pieces.size() && !near; ++p) {
      near = distance_to_segment(ring.pieces[p], x, y) <= max_distance_px + ring.half_width_px[p];
    }
    if (!near) return false;
  }
  return true;
}

std::size_t count_arc_false_positives(std::span<const Segment2> detected, std::span<const TruthSegment> truth,
                                      std::span<const RingImage> rings, const MatchParams& match) {
  std::size_t n = 0;
  for (const Segment2& d : detected) {
    const MatchCounts alone = match_segments({&d, 1}, truth, match);
    if (alone.detections == 0 || alone.true_positives > 0) continue;  // right, or don't care
    for (const RingImage& ring : rings) {
      if (lies_on_ring(d, ring, match.max_distance_px)) {
        ++n;
        break;
      }
    }
  }
  return n;
}

}  // namespace ringlet::vision::evaluate
