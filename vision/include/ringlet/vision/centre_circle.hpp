#pragma once
// The centre circle, found on the ground plane as a whole before any straight line is fitted.
//
// Why before: pieces of the circle, fitted one at a time, look straight (a 30° arc of the 0.75 m
// circle bends 2.6 cm away from its chord, less than the lines' 4 cm inlier band), and a RANSAC
// line through a chord takes points of two arc parts. A circle hypothesis made from two points
// and the known radius sees the whole arc at once; its points then leave the pool before the
// line rounds start, and line pieces that lie on it are not reported as lines.
//
// Hypotheses: two sample points 0.15 m to 2r apart and the radius r0 give two centres (the
// circles of radius r0 through both); each is scored on the sample by MSAC's truncated quadratic
// (a point within the wide band counts 1 − (distance / band)², so points hugging a circle outscore
// lines that merely cross its band). The best three distinct ones (centres ≥ 0.3 m apart) are
// refined in turn on every candidate by the geometric fit (radius held at r0 until the arc covers
// enough of the circle to measure it) and judged; the first that passes is the circle:
//   - enough inliers, covering enough of the circle (10° bins holding ≥ 2 points each);
//   - the arc is CURVED like the circle: its inliers, in runs of occupied bins cut into chunks of
//     at most 90°, each bend away from their chord towards the centre by more than half the
//     circle's curvature 1/(2r0) (fit_bend); chunks that are straight are a line that merely
//     touches the band (a tangent, an L corner) — the circle is refused unless the curved chunks
//     cover the minimum and outnumber the straight ones;
//   - the inliers hug the circle: their RMS distance from it is well inside the band (lines that
//     merely cross the band spread over all of it), a little looser when much of the arc is seen;
//   - a radius within r0 × (1 ± tolerance).
// Confidence in [0, 1] = coverage (curved degrees / 180, at most 1) × count (inliers / 40, at
// most 1) × fit (1 − RMS / band).
//
// Allocation-free after construction; the deadline is checked before every trial.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "ringlet/hal/geometry.hpp"
#include "ringlet/vision/deadline.hpp"
#include "ringlet/vision/fit.hpp"
#include "ringlet/vision/scan_points.hpp"

namespace ringlet::vision {

struct CircleParams {
  double radius_m = 0.75;                // r0: the SPL centre circle (to the middle of the paint)
  double radius_tolerance = 0.25;        // accepted radius r0 × (1 ± this)
  int max_trials = 40;                   // two-point hypotheses per frame
  int max_sample_points = 96;            // the trials see every k-th candidate, at most this many
  double min_pair_distance_m = 0.15;     // closer pairs fix the centre poorly
  double hypothesis_band_m = 0.06;       // a sample point supports a hypothesis this close to it
  double band_m = 0.04;                  // inlier band of the refined circle (the lines' tolerance)
  double max_direction_deg = 30.0;       // a point whose paint runs more than this off the circle's
                                         //   tangent in the picture (its run's edges tell) is no
                                         //   inlier: a line crossing the band at the end of a
                                         //   straight one bent the pair into a false arc
                                         //   (val2_s101 frame 1665); 0: off
  int min_inliers = 12;
  double min_coverage_deg = 50.0;        // curved arc needed, in 10° bins of ≥ 2 points
  double tangent_rms_ratio = 0.6;        // judged on its points' tangents (a far circle): a
                                         //   straight line's points cover up to ~50° of the band
                                         //   with their paint near the tangent, so the members
                                         //   must also fit the circle better than one line: RMS
                                         //   below this × their line fit's, and cover one
                                         //   unbroken arc of min_coverage_deg (two lines of a
                                         //   corner touch a circle in two places)
  double free_radius_coverage_deg = 120.0;  // below this much arc the radius is held at r0
  double max_rms_ratio = 0.3;            // the inliers hug the circle: RMS ≤ this × band_m, or
  double wide_arc_deg = 100.0;           //   with at least this much arc seen,
  double wide_arc_rms_ratio = 0.45;      //   RMS ≤ this × band_m. Straight lines crossing the band
                                         //   spread over it (RMS ≈ band / √3 ≈ 0.58 band). 120°
                                         //   refused a circle 5 m away seen over 100°, 60° of it
                                         //   curved and none straight: its points lie 14 mm from
                                         //   it (RMS), a pixel's depth there (val_s101 frame 1102)
  double noise_floor_m = 0.005;          // fit_bend's noise floor
  std::uint64_t seed_salt = 0xC1C1E;     // the circle's PRNG stream: SplitMix64::for_frame(seed ^ salt)
};

struct CentreCircle {
  bool seen = false;
  hal::RobotPoint centre{};
  double radius_m = 0.0;
  int inliers = 0;
  double confidence = 0.0;   // [0, 1], see above
  double coverage_deg = 0.0; // arc seen (10° bins holding ≥ 2 inliers)
  double rms_m = 0.0;        // RMS of the inliers' distance from the circle
};

struct CircleStats {
  int trials_run = 0;
  int trials_skipped = 0;  // cut by the deadline
  int points_used = 0;     // the trials' sample
  bool rejected = false;   // the best hypothesis was judged and refused ...
  CentreCircle refused{};  // ... as this (seen false; its coverage, RMS and inliers say why)
  int curved_bins = 0;     // the judged circle's arc_coverage()
  int straight_bins = 0;
};

/// How much of a circle a set of points covers, and whether it is curved like it.
struct ArcCoverage {
  int bins = 0;           // 10° bins holding ≥ 2 points
  int curved_bins = 0;    // of those, in chunks that bend like the circle
  int straight_bins = 0;  // ... in chunks that are straight (a line touching the band)
  int longest_run = 0;    // the most consecutive bins holding any point, around the circle
};

/// Storage arc_coverage() sorts members in, reserved once for a capacity.
struct ArcScratch {
  explicit ArcScratch(std::size_t capacity) {
    bin.reserve(capacity);
    index.reserve(capacity);
  }
  std::vector<int> bin;    // each member's 10° bin around the centre
  std::vector<int> index;  // the members in bin order
};

class CentreCircleFinder {
 public:
  CentreCircleFinder(const CircleParams& params, std::size_t capacity);

  /// Finds the centre circle among `candidates` (ground points) for frame `frame`. `seed` is the
  /// RANSAC seed (the circle draws from its own stream of it). Trials stop at the deadline; the
  /// best hypothesis so far is still judged.
  CentreCircle find(std::span<const CandidatePoint> candidates, std::uint64_t frame, std::uint64_t seed,
                    const Deadline& deadline, CircleStats& stats, int max_trials = -1) noexcept;

  /// Judges `circle` on the points `members` of `points` (indices): coverage, curvature, RMS, and
  /// fills confidence (0 when refused). Used for the circle the line rounds find too.
  /// `tangent_members`: every member's paint was seen to run along the circle's tangent, which
  /// shows the curve where the positions are too noisy to (a far circle): the arc's coverage
  /// then stands for its curvature. `coverage_out`, if given, receives the arc_coverage() judged.
  [[nodiscard]] static CentreCircle judge(const Circle2& circle, std::span<const hal::RobotPoint> points,
                                          std::span<const int> members, const CircleParams& params,
                                          ArcScratch& scratch, bool tangent_members = false,
                                          ArcCoverage* coverage_out = nullptr) noexcept;

  [[nodiscard]] const CircleParams& params() const noexcept { return params_; }

 private:
  std::size_t gather(const Circle2& c, double band) noexcept;

  CircleParams params_;
  std::vector<hal::RobotPoint> points_;
  std::vector<hal::RobotPoint> along_;   // their paint's direction (CandidatePoint::ground_along
  std::vector<hal::RobotPoint> across_;  //   and ground_across)
  double max_direction_tan_;             // tan(max_direction_deg), < 0: no gate
  std::vector<int> sample_;
  std::vector<int> eligible_;  // one trial's candidates for its second point
  std::vector<int> members_;
  ArcScratch arc_;
};

/// Refines `start` on `members` of `points`: the geometric fit, radius held at r0 unless the
/// members cover free_radius_coverage_deg; none when the fit fails or leaves the radius range.
[[nodiscard]] std::optional<Circle2> refine_centre_circle(const Circle2& start, std::span<const hal::RobotPoint> points,
                                                          std::span<const int> members, const CircleParams& params,
                                                          ArcScratch& scratch) noexcept;

/// Coverage of `c` by `members`, and how many of the covered bins are curved like it.
[[nodiscard]] ArcCoverage arc_coverage(const Circle2& c, std::span<const hal::RobotPoint> points,
                                       std::span<const int> members, const CircleParams& params,
                                       ArcScratch& scratch) noexcept;

}  // namespace ringlet::vision
