// The head pitch the field lines agree with (pitch_check.hpp).
#include "ringlet/vision/pitch_check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "ringlet/hal/geometry.hpp"

namespace ringlet::vision {
namespace {

constexpr std::size_t kMaxSegments = 24;  // RANSAC reports at most 12 lines; room for more

struct Picked {
  std::array<ImageSegment, kMaxSegments> seg{};
  std::array<double, kMaxSegments> length{};
  std::size_t count = 0;
};

double length_px(const ImageSegment& s) noexcept { return std::sqrt((s.b.u - s.a.u) * (s.b.u - s.a.u) + (s.b.v - s.a.v) * (s.b.v - s.a.v)); }

// Pieces of one line: nearly the same direction and each end close to the other's line.
bool one_line(const ImageSegment& p, double lp, const ImageSegment& q, double lq, const PitchCheckParams& params) noexcept {
  const double pu = (p.b.u - p.a.u) / lp, pv = (p.b.v - p.a.v) / lp;
  const double qu = (q.b.u - q.a.u) / lq, qv = (q.b.v - q.a.v) / lq;
  if (std::abs(pu * qv - pv * qu) > std::sin(hal::deg_to_rad(params.collinear_deg))) return false;
  const auto off = [&](const hal::Pixel& x) { return std::abs((x.u - p.a.u) * pv - (x.v - p.a.v) * pu); };
  return off(q.a) <= params.collinear_px && off(q.b) <= params.collinear_px;
}

using PairMask = std::array<bool, kMaxSegments * kMaxSegments>;  // [i * kMaxSegments + j], i < j: not one line
using SegmentMask = std::array<bool, kMaxSegments>;                // still used (not left out)

// The weighted mean square of the active pairs' sin(departure from parallel or square) at one
// pitch offset; false when an active segment leaves the ground there.
bool departure(const Picked& s, const PairMask& informative, const SegmentMask& active, const hal::CameraIntrinsics& k,
               const hal::CameraMount& mount, hal::CameraPosture posture, double offset_rad, double& mean_square) noexcept {
  posture.head.pitch += offset_rad;
  const hal::CameraPose pose = hal::CameraPose::from_posture(mount, posture);
  std::array<hal::RobotPoint, kMaxSegments> dir{};
  for (std::size_t i = 0; i < s.count; ++i) {
    if (!active[i]) continue;
    const auto a = hal::pixel_to_ground(k, pose, s.seg[i].a);
    const auto b = hal::pixel_to_ground(k, pose, s.seg[i].b);
    if (!a || !b) return false;
    const double dx = b->x - a->x, dy = b->y - a->y;
    const double n = std::sqrt(dx * dx + dy * dy);
    if (n <= 0.0) return false;
    dir[i] = {dx / n, dy / n};
  }
  double sum = 0.0, weights = 0.0;
  for (std::size_t i = 0; i < s.count; ++i) {
    for (std::size_t j = i + 1; j < s.count; ++j) {
      if (!active[i] || !active[j] || !informative[i * kMaxSegments + j]) continue;
      const double sine = std::abs(dir[i].x * dir[j].y - dir[i].y * dir[j].x);
      const double cosine = std::abs(dir[i].x * dir[j].x + dir[i].y * dir[j].y);
      const double d = std::min(sine, cosine);  // sin of the departure from the nearer of 0° and 90°
      const double w = std::sqrt(s.length[i] * s.length[j]);
      sum += w * d * d;
      weights += w;
    }
  }
  mean_square = weights > 0.0 ? sum / weights : 0.0;
  return true;
}

// The grid search over the active segments: the best offset (index) and its mean square, and the
// mean square at the given pitch.
struct Search {
  bool ok = false;  // the active segments are on the ground at the given pitch
  int pairs = 0;
  int best_i = 0;
  double best = 0.0, at_given = 0.0;
};

Search search(const Picked& s, const PairMask& informative, const SegmentMask& active, const hal::CameraIntrinsics& k,
              const hal::CameraMount& mount, const hal::CameraPosture& posture, int steps, double step) noexcept {
  Search r;
  for (std::size_t i = 0; i < s.count; ++i) {
    for (std::size_t j = i + 1; j < s.count; ++j) r.pairs += active[i] && active[j] && informative[i * kMaxSegments + j] ? 1 : 0;
  }
  if (!departure(s, informative, active, k, mount, posture, 0.0, r.at_given)) return r;
  r.ok = true;
  r.best = r.at_given;
  for (int i = -steps; i <= steps; ++i) {
    double m = 0.0;
    if (!departure(s, informative, active, k, mount, posture, i * step, m)) continue;
    // Ties keep the offset nearest the given pitch.
    if (m < r.best || (m == r.best && std::abs(i) < std::abs(r.best_i))) {
      r.best = m;
      r.best_i = i;
    }
  }
  return r;
}

double to_deg(double mean_square) noexcept { return hal::rad_to_deg(std::asin(std::min(1.0, std::sqrt(mean_square)))); }

}  // namespace

PitchCheck estimate_pitch_offset(std::span<const ImageSegment> segments, const hal::CameraIntrinsics& k,
                                 const hal::CameraMount& mount, const hal::CameraPosture& posture,
                                 const PitchCheckParams& params) noexcept {
  PitchCheck out;
  const int steps = params.step_deg > 0.0 ? static_cast<int>(std::floor(params.range_deg / params.step_deg)) : 0;
  const double step = hal::deg_to_rad(params.step_deg);
  // The segments long enough and on the ground at the given pitch. An offset at which one of them
  // leaves the ground (an end at or above the horizon) is not a candidate: dropping the segment
  // there instead would favour the offsets that drop the most disagreeing ones.
  const hal::CameraPose given = hal::CameraPose::from_posture(mount, posture);
  Picked s;
  for (const ImageSegment& seg : segments) {
    if (s.count == kMaxSegments) break;
    const double len = length_px(seg);
    if (!(len >= params.min_length_px)) continue;
    if (!hal::pixel_to_ground(k, given, seg.a) || !hal::pixel_to_ground(k, given, seg.b)) continue;
    s.seg[s.count] = seg;
    s.length[s.count] = len;
    ++s.count;
  }
  out.segments = static_cast<int>(s.count);
  PairMask informative{};
  for (std::size_t i = 0; i < s.count; ++i) {
    for (std::size_t j = i + 1; j < s.count; ++j) {
      informative[i * kMaxSegments + j] = !one_line(s.seg[i], s.length[i], s.seg[j], s.length[j], params);
    }
  }
  SegmentMask active{};
  std::fill(active.begin(), active.begin() + static_cast<std::ptrdiff_t>(s.count), true);
  const int min_pairs = std::max(params.min_pairs, 1);
  Search r = search(s, informative, active, k, mount, posture, steps, step);
  out.pairs = r.pairs;
  out.residual_at_given_deg = to_deg(r.at_given);
  if (!r.ok || r.pairs < min_pairs) return out;
  // One segment that no pitch squares with the rest (an arc piece, a cross's bar, a post's edge)
  // spoils them all: drop the one whose loss helps most, up to a third of them, while the
  // residual is too large and enough pairs remain.
  const int max_dropped = std::max(1, out.segments / 3);
  while (to_deg(r.best) > params.max_residual_deg && out.dropped < max_dropped) {
    Search better = r;
    std::size_t drop = s.count;
    for (std::size_t i = 0; i < s.count; ++i) {
      if (!active[i]) continue;
      active[i] = false;
      const Search t = search(s, informative, active, k, mount, posture, steps, step);
      active[i] = true;
      if (t.ok && t.pairs >= min_pairs && t.best < better.best) {
        better = t;
        drop = i;
      }
    }
    if (drop == s.count) break;
    active[drop] = false;
    r = better;
    ++out.dropped;
  }
  out.pairs = r.pairs;
  out.offset_deg = r.best_i * params.step_deg;
  out.residual_deg = to_deg(r.best);
  // At the range's end the best may lie beyond it: no estimate.
  out.valid = out.residual_deg <= params.max_residual_deg && std::abs(r.best_i) < steps;
  return out;
}

PitchCorrection correct_head_pitch(VisionPipeline& pipeline, const hal::FrameView& frame,
                                   const hal::CameraPosture& posture, const PitchCheckParams& params) noexcept {
  PitchCorrection out;
  out.posture = posture;
  const VisionConfig& config = pipeline.config();
  for (std::size_t round = 0; round < out.rounds.size(); ++round) {
    pipeline.forget_history();
    const VisionResult& r = pipeline.process(frame, out.posture, Deadline{});
    std::array<ImageSegment, kMaxLines> segments{};
    const std::size_t n = std::min(r.line_count, segments.size());
    for (std::size_t i = 0; i < n; ++i) segments[i] = {r.lines[i].image_start, r.lines[i].image_end};
    const PitchCheck c = estimate_pitch_offset(std::span<const ImageSegment>(segments.data(), n), config.intrinsics,
                                               config.mount, out.posture, params);
    out.rounds[round] = c;
    out.round_count = static_cast<int>(round) + 1;
    if (!c.valid || std::abs(c.offset_deg) < 0.1) break;
    using R = hal::NaoHeadRange;
    out.posture.head.pitch = hal::deg_to_rad(
        std::clamp(hal::rad_to_deg(out.posture.head.pitch) + c.offset_deg, R::kMinPitchDeg, R::kMaxPitchDeg));
  }
  return out;
}

}  // namespace ringlet::vision
