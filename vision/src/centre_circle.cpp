// The centre circle on the ground: two-point hypotheses of known radius, the geometric refit and
// the judgement (coverage, curvature, radius). See centre_circle.hpp for the reasons.
#include "ringlet/vision/centre_circle.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "ringlet/hal/portable_math.hpp"
#include "ringlet/vision/prng.hpp"

namespace ringlet::vision {
namespace {

constexpr int kBins = 36;  // 10° each
constexpr int kMaxChunkBins = 9;  // arcs are judged in chunks of at most 90° (fit_bend needs a function of t)
constexpr int kMinChunkBins = 3;  // shorter chunks bend too little to tell
constexpr std::size_t kKeep = 3;     // hypotheses judged
constexpr double kMinApart = 0.3;    // m between the centres of distinct hypotheses

struct Scored {
  Circle2 circle{};
  double score = 0.0;
};

double distance(const hal::RobotPoint& a, const hal::RobotPoint& b) noexcept { return hal::portable_hypot(b.x - a.x, b.y - a.y); }

double squared_distance(const hal::RobotPoint& a, const hal::RobotPoint& b) noexcept {
  const double dx = b.x - a.x, dy = b.y - a.y;
  return dx * dx + dy * dy;
}

/// Decides whether a distance lies in [lo, hi] from its square where that is clear, so that most
/// points need no square root (the trials' and the gathers' cost); within a hair of either bound
/// the caller measures the distance itself, so every answer is the one the distance gives.
class DistanceRange {
 public:
  enum class Verdict : std::uint8_t { kOut, kIn, kMeasure };
  DistanceRange(double lo, double hi) noexcept
      : out_below_(lo > 0.0 ? lo * lo * (1.0 - kGuard) : -1.0),
        in_above_(lo > 0.0 ? lo * lo * (1.0 + kGuard) : -1.0),
        in_below_(hi * hi * (1.0 - kGuard)),
        out_above_(hi * hi * (1.0 + kGuard)) {}
  [[nodiscard]] Verdict of(double squared) const noexcept {
    if (squared < out_below_ || squared > out_above_) return Verdict::kOut;
    return squared > in_above_ && squared < in_below_ ? Verdict::kIn : Verdict::kMeasure;
  }

 private:
  static constexpr double kGuard = 1e-9;  // far above the rounding of a square, far below any tolerance
  double out_below_, in_above_, in_below_, out_above_;
};

int bin_of(const Circle2& c, const hal::RobotPoint& p) noexcept {
  const double a = std::atan2(p.y - c.centre.y, p.x - c.centre.x);  // [−π, π]
  const int b = static_cast<int>(std::floor((a + std::numbers::pi) / (2.0 * std::numbers::pi) * kBins));
  return std::clamp(b, 0, kBins - 1);
}

double rms_of(const Circle2& c, std::span<const hal::RobotPoint> points, std::span<const int> members) noexcept {
  return circle_rms(c, {points, members});
}

}  // namespace

ArcCoverage arc_coverage(const Circle2& c, std::span<const hal::RobotPoint> points, std::span<const int> members,
                         const CircleParams& params, ArcScratch& scratch) noexcept {
  ArcCoverage out;
  // Each member's bin once (atan2 is most of this stage's cost), then a counting sort by bin:
  // members in angle order, so that a chunk of bins is a contiguous range of indices. Within a
  // bin they keep the order they came in (ascending, as every caller collects them).
  scratch.bin.clear();
  std::array<int, kBins> count{};
  for (const int m : members) {
    const int b = bin_of(c, points[static_cast<std::size_t>(m)]);
    scratch.bin.push_back(b);
    ++count[static_cast<std::size_t>(b)];
  }
  std::array<bool, kBins> occupied{};
  for (int b = 0; b < kBins; ++b) {
    occupied[static_cast<std::size_t>(b)] = count[static_cast<std::size_t>(b)] >= 2;
    out.bins += occupied[static_cast<std::size_t>(b)] ? 1 : 0;
  }
  if (out.bins == 0) return out;
  // Around the circle: a run may cross ±180° (the near side of a circle ahead does).
  for (int b = 0, run = 0; b < 2 * kBins; ++b) {
    run = count[static_cast<std::size_t>(b % kBins)] > 0 ? run + 1 : 0;
    out.longest_run = std::max(out.longest_run, std::min(run, kBins));
  }
  // The first index of each bin in angle order.
  std::array<std::size_t, kBins + 1> first{};
  {
    std::size_t at = 0;
    for (int b = 0; b < kBins; ++b) {
      first[static_cast<std::size_t>(b)] = at;
      at += static_cast<std::size_t>(count[static_cast<std::size_t>(b)]);
    }
    first[kBins] = at;
  }
  scratch.index.resize(members.size());
  {
    std::array<std::size_t, kBins> next{};
    std::copy(first.begin(), first.begin() + kBins, next.begin());
    for (std::size_t i = 0; i < members.size(); ++i) {
      scratch.index[next[static_cast<std::size_t>(scratch.bin[i])]++] = members[i];
    }
  }
  const double c0 = 1.0 / (2.0 * params.radius_m);
  const auto judge_chunk = [&](int from, int len) {  // bins from .. from + len − 1 (no wrap)
    if (len < kMinChunkBins) return;
    const std::size_t lo = first[static_cast<std::size_t>(from)];
    const std::size_t hi = first[static_cast<std::size_t>(from + len)];
    const IndexedPoints chunk{points, std::span<const int>(scratch.index).subspan(lo, hi - lo)};
    const auto line = fit_line_tls(chunk);
    const auto bend = line ? fit_bend(*line, chunk, params.noise_floor_m) : std::nullopt;
    if (!bend) return;
    // Towards the centre: the chunk's middle lies farther from the centre than its ends.
    const double side = line->signed_distance(c.centre) >= 0.0 ? 1.0 : -1.0;
    const double oriented = bend->c * side;
    if (oriented > c0 / 2.0) {
      out.curved_bins += len;
    } else {
      out.straight_bins += len;
    }
  };
  // Runs of occupied bins. Bin arithmetic does not wrap here: a run crossing ±180° is judged as
  // two runs, which only matters for chunks that become shorter than kMinChunkBins.
  int b = 0;
  while (b < kBins) {
    if (!occupied[static_cast<std::size_t>(b)]) {
      ++b;
      continue;
    }
    int e = b;
    while (e < kBins && occupied[static_cast<std::size_t>(e)]) ++e;
    const int len = e - b;
    const int chunks = (len + kMaxChunkBins - 1) / kMaxChunkBins;
    int at = b;
    for (int k = 0; k < chunks; ++k) {
      const int part = (len * (k + 1)) / chunks - (len * k) / chunks;
      judge_chunk(at, part);
      at += part;
    }
    b = e;
  }
  return out;
}

std::optional<Circle2> refine_centre_circle(const Circle2& start, std::span<const hal::RobotPoint> points,
                                            std::span<const int> members, const CircleParams& params,
                                            ArcScratch& scratch) noexcept {
  const IndexedPoints pts{points, members};
  const Circle2 held{start.centre, params.radius_m};
  auto fit = fit_circle_geometric(pts, held, true);
  if (!fit) return std::nullopt;
  // Enough arc to measure the radius: let it move (the camera's pose error shows as a radius error).
  if (arc_coverage(*fit, points, members, params, scratch).bins * 10.0 >= params.free_radius_coverage_deg) {
    if (const auto free = fit_circle_geometric(pts, *fit, false)) fit = free;
  }
  if (std::abs(fit->radius - params.radius_m) > params.radius_tolerance * params.radius_m) return std::nullopt;
  return fit;
}

CentreCircle CentreCircleFinder::judge(const Circle2& circle, std::span<const hal::RobotPoint> points,
                                       std::span<const int> members, const CircleParams& params,
                                       ArcScratch& scratch, bool tangent_members, ArcCoverage* coverage_out) noexcept {
  CentreCircle out;
  out.centre = circle.centre;
  out.radius_m = circle.radius;
  out.inliers = static_cast<int>(members.size());
  out.rms_m = rms_of(circle, points, members);
  const ArcCoverage cov = arc_coverage(circle, points, members, params, scratch);
  if (coverage_out != nullptr) *coverage_out = cov;
  out.coverage_deg = cov.bins * 10.0;
  const bool radius_ok = std::abs(circle.radius - params.radius_m) <= params.radius_tolerance * params.radius_m;
  const int curved_bins = tangent_members ? cov.bins : cov.curved_bins;
  bool curved = curved_bins * 10.0 >= params.min_coverage_deg;
  if (curved && tangent_members) {
    const IndexedPoints all{points, members};
    const auto line = fit_line_tls(all);
    curved = cov.longest_run * 10.0 >= params.min_coverage_deg &&
             (!line || out.rms_m < params.tangent_rms_ratio * line_rms(*line, all));
  } else if (curved) {
    curved = cov.curved_bins > cov.straight_bins;
  }
  const bool hugs = out.rms_m <= params.max_rms_ratio * params.band_m ||
                    (out.coverage_deg >= params.wide_arc_deg && out.rms_m <= params.wide_arc_rms_ratio * params.band_m);
  out.seen = radius_ok && curved && hugs && out.inliers >= params.min_inliers;
  if (out.seen) {
    const double coverage = std::min(1.0, curved_bins * 10.0 / 180.0);
    const double count = std::min(1.0, out.inliers / 40.0);
    const double fit = std::clamp(1.0 - out.rms_m / params.band_m, 0.0, 1.0);
    out.confidence = coverage * count * fit;
  }
  return out;
}

CentreCircleFinder::CentreCircleFinder(const CircleParams& params, std::size_t capacity)
    : params_(params),
      max_direction_tan_(direction_gate_tan(params.max_direction_deg)),
      arc_(capacity) {
  points_.reserve(capacity);
  along_.reserve(capacity);
  across_.reserve(capacity);
  sample_.reserve(capacity);
  eligible_.reserve(capacity);
  members_.reserve(capacity);
}

std::size_t CentreCircleFinder::gather(const Circle2& c, double band) noexcept {
  members_.clear();
  const DistanceRange ring(c.radius - band, c.radius + band);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const DistanceRange::Verdict v = ring.of(squared_distance(points_[i], c.centre));
    if (v == DistanceRange::Verdict::kOut) continue;
    if (v != DistanceRange::Verdict::kIn && std::abs(distance(points_[i], c.centre) - c.radius) > band) continue;
    // The tangent there: at right angles to the radius.
    const double tx = c.centre.y - points_[i].y, ty = points_[i].x - c.centre.x;
    if (!paint_runs_along(along_[i], across_[i], tx, ty, max_direction_tan_)) continue;
    members_.push_back(static_cast<int>(i));
  }
  return members_.size();
}

CentreCircle CentreCircleFinder::find(std::span<const CandidatePoint> candidates, std::uint64_t frame,
                                      std::uint64_t seed, const Deadline& deadline, CircleStats& stats,
                                      int max_trials) noexcept {
  stats = CircleStats{};
  points_.clear();
  along_.clear();
  across_.clear();
  for (std::size_t i = 0; i < candidates.size() && points_.size() < points_.capacity(); ++i) {
    points_.push_back(candidates[i].ground);
    along_.push_back(candidates[i].ground_along);
    across_.push_back(candidates[i].ground_across);
  }
  const auto min_inliers = static_cast<std::size_t>(std::max(params_.min_inliers, 3));
  if (points_.size() < min_inliers) return {};
  const std::size_t step =
      std::max<std::size_t>(1, (points_.size() + static_cast<std::size_t>(std::max(params_.max_sample_points, 1)) - 1) /
                                   static_cast<std::size_t>(std::max(params_.max_sample_points, 1)));
  sample_.clear();
  for (std::size_t i = 0; i < points_.size(); i += step) sample_.push_back(static_cast<int>(i));
  stats.points_used = static_cast<int>(sample_.size());

  const double r0 = params_.radius_m;
  const double max_pair = 2.0 * r0;
  SplitMix64 rng = SplitMix64::for_frame(seed ^ params_.seed_salt, frame);
  const int trials = max_trials >= 0 ? max_trials : params_.max_trials;
  // The best few distinct hypotheses (centres kMinApart apart), by score: the one with most
  // support may be a false one made of lines crossing the band, and the true circle the next.
  std::array<Scored, kKeep> kept{};
  std::size_t kept_count = 0;
  const auto order = [&] {  // insertion sort, best first (stable: earlier trials win ties)
    for (std::size_t i = 1; i < kept_count; ++i) {
      for (std::size_t j = i; j > 0 && kept[j].score > kept[j - 1].score; --j) std::swap(kept[j], kept[j - 1]);
    }
  };
  const auto keep = [&](const Circle2& c, double score) {
    for (std::size_t i = 0; i < kept_count; ++i) {
      if (distance(kept[i].circle.centre, c.centre) < kMinApart) {
        if (score > kept[i].score) kept[i] = {c, score};
        order();
        return;
      }
    }
    if (kept_count < kKeep) {
      kept[kept_count++] = {c, score};
    } else if (score > kept[kKeep - 1].score) {
      kept[kKeep - 1] = {c, score};
    } else {
      return;
    }
    order();
  };
  int t = 0;
  const double band = params_.hypothesis_band_m;
  const DistanceRange pair_range(params_.min_pair_distance_m, max_pair);
  const DistanceRange band_range(r0 - band, r0 + band);
  for (; t < trials; ++t) {
    if (deadline.expired()) break;
    ++stats.trials_run;
    const hal::RobotPoint& a = points_[static_cast<std::size_t>(sample_[rng.below(sample_.size())])];
    // The second point: uniform among the sample points at a usable distance from the first.
    eligible_.clear();
    for (const int j : sample_) {
      const hal::RobotPoint& q = points_[static_cast<std::size_t>(j)];
      const DistanceRange::Verdict v = pair_range.of(squared_distance(a, q));
      if (v == DistanceRange::Verdict::kOut) continue;
      if (v == DistanceRange::Verdict::kMeasure) {
        const double d = distance(a, q);
        if (d < params_.min_pair_distance_m || d >= max_pair) continue;
      }
      eligible_.push_back(j);
    }
    if (eligible_.empty()) continue;
    const hal::RobotPoint b = points_[static_cast<std::size_t>(eligible_[rng.below(eligible_.size())])];
    // The two circles of radius r0 through a and b: centres on the perpendicular bisector.
    const double d = distance(a, b);
    const double h = std::sqrt(std::max(0.0, r0 * r0 - d * d / 4.0));
    const hal::RobotPoint mid{(a.x + b.x) / 2.0, (a.y + b.y) / 2.0};
    const double nx = -(b.y - a.y) / d, ny = (b.x - a.x) / d;
    for (const double side : {1.0, -1.0}) {
      const Circle2 c{{mid.x + side * h * nx, mid.y + side * h * ny}, r0};
      // MSAC's truncated quadratic: a point counts 1 on the circle, less towards the band's edge,
      // so points hugging a circle outscore lines that merely cross its band.
      double score = 0.0;
      for (const int j : sample_) {
        const hal::RobotPoint& q = points_[static_cast<std::size_t>(j)];
        if (band_range.of(squared_distance(q, c.centre)) == DistanceRange::Verdict::kOut) continue;
        const double e = (distance(q, c.centre) - r0) / band;
        if (std::abs(e) < 1.0) score += 1.0 - e * e;
      }
      keep(c, score);
    }
  }
  stats.trials_skipped = trials - t;

  // Dense from here: every candidate near a hypothesis, then the refit on the narrow band; the
  // first (best supported) that passes the judgement is the circle.
  CentreCircle out;
  for (std::size_t h = 0; h < kept_count && !out.seen; ++h) {
    if (kept[h].score < 3.0) break;
    Circle2 circle = kept[h].circle;
    if (gather(circle, band) < min_inliers) continue;
    for (int iteration = 0; iteration < 3; ++iteration) {
      const auto refined = refine_centre_circle(circle, points_, members_, params_, arc_);
      if (!refined) break;
      const bool moved =
          distance(refined->centre, circle.centre) > 1e-4 || std::abs(refined->radius - circle.radius) > 1e-4;
      circle = *refined;
      if (gather(circle, params_.band_m) < min_inliers || !moved) break;
    }
    gather(circle, params_.band_m);
    ArcCoverage cov;
    const CentreCircle judged = judge(circle, points_, members_, params_, arc_, false, &cov);
    if (judged.seen || h == 0) {  // the stats describe the accepted circle, or the best refused one
      stats.curved_bins = cov.curved_bins;
      stats.straight_bins = cov.straight_bins;
      stats.refused = judged.seen ? CentreCircle{} : judged;
    }
    out = judged;
  }
  stats.rejected = kept_count > 0 && !out.seen;
  return out.seen ? out : CentreCircle{};
}

}  // namespace ringlet::vision
