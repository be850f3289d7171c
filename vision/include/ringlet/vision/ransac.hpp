#pragma once
// Field lines from candidate points by RANSAC, after Mi-Pal (§6.2 of their report): MAX_TRIALS
// random two-point hypotheses per line and only every RANSAC_SKIP-th candidate used at all. Lines
// are extracted one after another (inliers removed), refined by total least squares, split at
// gaps, merged when collinear, and arcs of the centre circle are recognised instead of being
// reported as short straight lines. All geometry is on the ground (robot frame), where a tolerance
// in metres means the same thing near and far.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/vision/centre_circle.hpp"
#include "ringlet/vision/deadline.hpp"
#include "ringlet/vision/fit.hpp"
#include "ringlet/vision/line_check.hpp"
#include "ringlet/vision/scan_points.hpp"

namespace ringlet::vision {

inline constexpr std::size_t kMaxLines = 12;
inline constexpr int kPartnerDraws = 8;  // draws for a trial's second point along the first's paint
// An image end this near the picture's edge is cut by it: the scan finds no run there (a run
// needs field beyond the paint), so a line's last candidates lie a few pixels in. 4 px missed
// some (validation arc pieces 12 / 5 against 12 / 3 at 8 px, F1 the same; 12 px: the same as 8).
inline constexpr double kEdgeMarginPx = 8.0;

struct RansacParams {
  int max_trials = 30;               // MAX_TRIALS: two-point hypotheses per extracted line; the
                                     //   second point is drawn along the first one's paint (up to
                                     //   kPartnerDraws draws, ransac.cpp): short lines are
                                     //   hypothesised far more often (30 trials did what 100
                                     //   blind ones did on the validation sets)
  int skip = 10;                     // RANSAC_SKIP: hypotheses are drawn from, and scored on, every
                                     //   skip-th point still unassigned; the chosen line is then
                                     //   refitted, cut and measured on every candidate point
  int max_lines = 12;                // extraction rounds (≤ kMaxLines segments are reported)
  int max_empty_rounds = 2;          // extraction ends at the round that is the this-many-th to
                                     //   find too few inliers for a line (1 ended it at the first:
                                     //   clutter winning one round's sample hid the short lines
                                     //   left; unlimited scored the same and cost 3 % more of the
                                     //   vision budget at p99)
  int min_sample_points = 40;        // ... but the sample is never thinned below this many points
  int min_sampled_inliers = 2;       // a hypothesis needs this many sampled points to be tried
  int min_inliers = 6;               // a line (and each piece of it) needs this many candidates
  double inlier_base_m = 0.04;       // inlier tolerance = base + per_m × range of the point. The
  double inlier_per_m = 0.0;         //   range term is off by default: 0.015/m let far bands swallow
                                     //   clutter and neighbouring lines (F1 −0.08 in the evaluation)
  double max_direction_deg = 20.0;   // a point whose paint runs more than this off the line in the
                                     //   picture (its run's edges tell) is no inlier: where two
                                     //   lines meet or cross, the other's points stay out; 0: off
  double min_length_m = 0.15;        // shorter pieces are dropped
  double min_support = 0.45;         // inliers per scan line the piece's image crosses (its image
                                     //   length / scan stride): a painted line yields a candidate
                                     //   on most of them; clutter lined up by chance, on few
  double thin_width_px = 4.0;         // a piece whose paint is narrower than this in the picture
  double thin_min_support = 0.2;     //   needs only this support: a far line's run is often missed
                                     //   (too faint, or broken into dashes), yet lines up exactly
  double split_gap_m = 0.8;          // a gap longer than this between consecutive inliers splits
                                     //   (0.5 broke far lines, whose candidates come in stretches,
                                     //   into pieces judged alone: validation F1 −0.01, 1.0 merged
                                     //   what is not one line: −0.015)
  int max_split_depth = 3;           // a piece rejected as too sparse or as no paint is split at
                                     //   its widest gap and its parts judged alone, this many times
                                     //   deep (≤ 2^depth parts): lines past legs, into white feet
  double merge_angle_deg = 5.0;      // collinear merge: directions within this angle, and
  double merge_offset_m = 0.10;      //   each segment's endpoints this close to the other's line,
                                     //   and their gap along it below split_gap_m
  CircleParams circle{};             // the centre circle: radius, tolerance, its own stage's settings
  double circle_max_chord_m = 1.8;   // longer pieces are never taken for arcs
  double circle_rms_ratio = 0.6;     // an arc (Kåsa test): circle-fit RMS < this × line-fit RMS, and
  double circle_min_line_rms_m = 0.008;  //   the line fit's RMS above this (visible curvature)
  double arc_min_bend_z = 2.5;       // an arc (bend test): the piece bends from its chord by more than
                                     //   half the circle's curvature, this many standard errors from 0
  double tangent_circle_max_m = 1.0; // a straight piece this short may still touch a far circle:
                                     //   the circle r0 to either side is gathered (points whose
                                     //   paint runs along its tangent) and judged
  double tangent_circle_min_range_m = 1.5;  // ... and this far away (nearer, the bend shows; a
                                            //   0.2 m piece 1.9 m away bent too little: 2.0 let
                                            //   it through, val_s101 frame 1178; 1.0 cost F1)
  double tangent_max_rms_deg = 9.5;  //   and its points' paint must follow the tangent this
                                     //   closely (RMS): lines of a corner pass only the gate
  double arc_line_direction_ratio = 1.5;  // a piece that bends like an arc of no circle the frame
                                     //   shows stays a line when its points' paint follows the line
                                     //   this many times more closely (RMS) than the arc's tangents
  double arc_near_share = 0.5;       // a piece with this share of its points within twice the
                                     //   tolerance of the known circle is part of it
  double min_cut_piece_px = 30.0;    // a piece the picture's edge cuts (an end within
                                     //   kEdgeMarginPx of it) must be this long in the picture,
                                     //   unless the frame's circle is known: a far circle mostly
                                     //   outside the picture shows a few pixels of arc there, as
                                     //   straight as a line's end (validation: arc pieces 36 -> 15
                                     //   over three seeds, F1 the same; 40 px: F1 -0.001)
  double max_range_m = 13.0;         // a piece whose nearer end lies farther is not on the field:
                                     //   no paint lies farther than 11.8 m from a robot on the SPL
                                     //   field or its border (a border corner to the far corner),
                                     //   plus range error; the floor beyond the carpet, seen in
                                     //   daylight as field and paint, gives such pieces
  std::uint64_t seed = 0x52494E474C4554ULL;  // "RINGLET"; per frame: SplitMix64::for_frame
};

struct FieldLine {
  hal::Pixel image_start{};
  hal::Pixel image_end{};
  hal::RobotPoint ground_start{};
  hal::RobotPoint ground_end{};
  double length_m = 0.0;
  int inliers = 0;  // used (every skip-th) candidate points supporting it
};

struct RansacStats {
  int points_in = 0;             // candidates offered
  int points_used = 0;           // the first round's sample (every skip-th candidate)
  int sparse_rejected = 0;       // pieces with too little support for their image length
  int check_rejected = 0;        // pieces the picture does not show as paint (LineCheck)
  int trials_run = 0;
  int partner_draws = 0;         // second points drawn (up to kPartnerDraws per trial: along the first's paint)
  int trials_skipped = 0;        // cut by the deadline
  int lines_extracted = 0;       // extraction rounds that produced a segment (before merging)
  int arcs_rejected = 0;         // pieces taken as (part of) the centre circle, not reported as lines
  int circle_points = 0;         // candidates left out of the line rounds: on the known circle
  int merges = 0;
  int splits = 0;                // rejected pieces split at their widest gap and judged in parts
  int segments_dropped = 0;      // pieces beyond kMaxLines
  int cut_short = 0;             // short pieces the picture's edge cuts, not reported (min_cut_piece_px)
  int beyond_field = 0;          // pieces farther than any paint on the field (max_range_m)
  bool stopped_early = false;    // the deadline ended extraction: lines may be missing
  int points_left = 0;           // used points never examined because of that
};

struct LineSet {
  std::array<FieldLine, kMaxLines> lines{};
  std::size_t count = 0;
  CentreCircle circle{};
  RansacStats stats{};
};

/// Removes from lines[0, count) the pieces `drop` picks, keeping the others in order, in place (no
/// allocation); the new count. RANSAC's reporting rules and the pipeline's filters after it (robot
/// legs, standing objects) all drop lines this way.
template <class Drop>
[[nodiscard]] std::size_t drop_lines(std::span<FieldLine> lines, std::size_t count, const Drop& drop) noexcept {
  const auto end = lines.begin() + static_cast<std::ptrdiff_t>(std::min(count, lines.size()));
  return static_cast<std::size_t>(std::remove_if(lines.begin(), end, drop) - lines.begin());
}

/// Scratch storage for one candidate capacity, allocated once.
class RansacScratch {
 public:
  explicit RansacScratch(std::size_t capacity);

 private:
  friend class RansacLineFinder;
  std::vector<hal::RobotPoint> points_;   // used points (ground)
  std::vector<hal::Pixel> pixels_;        // their image positions
  std::vector<hal::RobotPoint> along_;    // their paint's direction (CandidatePoint::ground_along
  std::vector<hal::RobotPoint> across_;   //   and ground_across; {0, 0}: unknown)
  std::vector<int> pool_;                 // indices still unassigned (every candidate)
  std::vector<int> sample_;               // every skip-th index of pool_: the RANSAC trials' points
  std::vector<int> inliers_;
  std::vector<int> circle_members_;
  std::vector<int> arc_;    // the part of a piece on its fitted circle
  std::vector<int> piece_;  // one gap-free piece of a line
  std::vector<std::pair<double, int>> order_;
  ArcScratch arc_scratch_;
};

class RansacLineFinder {
 public:
  RansacLineFinder(const RansacParams& params, std::size_t capacity)
      : params_(params),
        scratch_(capacity),
        max_direction_tan_(direction_gate_tan(params.max_direction_deg)),
        max_tangent_rms_tan_(tan_deg(params.tangent_max_rms_deg)) {}

  /// Fits lines to `candidates` for frame `frame` (the PRNG stream). `max_trials`, `max_lines`
  /// and `skip` override the params when ≥ 0 (resp. ≥ 1 for skip) (degrade levels). Image endpoints come from projecting the ground
  /// endpoints with (k, pose). The deadline is checked before every trial. `circle`: the centre
  /// circle found before (CentreCircleFinder), or none: its points take no part in the line
  /// rounds, pieces lying on it are arcs, and it is the LineSet's circle (unless none was given
  /// and the rounds find one themselves). `max_point_tests`: no trial starts whose point tests, as
  /// the cost model counts them (trials × the first round's sample, plus the second points'
  /// draws, up to kPartnerDraws each), could pass it (the modelled budget's share, in lockstep);
  /// like the deadline, it stops the extraction (`stats.stopped_early`).
  void find(std::span<const CandidatePoint> candidates, std::uint64_t frame, const hal::CameraIntrinsics& k,
            const hal::CameraPose& pose, const Deadline& deadline, LineSet& out, int max_trials = -1,
            int max_lines = -1, int skip = -1, int scan_stride = 3, const CentreCircle* circle = nullptr,
            const LineCheck* check = nullptr,
            std::int64_t max_point_tests = std::numeric_limits<std::int64_t>::max()) noexcept;

  [[nodiscard]] const RansacParams& params() const noexcept { return params_; }

 private:
  // The per-point tests run for every point of every trial: defined here, to be inlined.
  [[nodiscard]] double tolerance(const hal::RobotPoint& p) const noexcept {
    return params_.inlier_per_m == 0.0 ? params_.inlier_base_m
                                       : params_.inlier_base_m + params_.inlier_per_m * std::sqrt(p.x * p.x + p.y * p.y);
  }
  [[nodiscard]] static double tan_deg(double deg) noexcept;
  [[nodiscard]] bool in_band(const Line2& l, int p) const noexcept {
    const hal::RobotPoint& q = scratch_.points_[static_cast<std::size_t>(p)];
    return std::abs(l.signed_distance(q)) <= tolerance(q);
  }
  [[nodiscard]] bool has_direction(int p) const noexcept {
    return knows_paint_direction(scratch_.along_[static_cast<std::size_t>(p)]);
  }
  /// Over `members` whose paint's direction is known and `direction(point)` gives a unit ground
  /// direction: the squares of the tangent of the angle, in the picture, between the two, summed.
  struct SquaredOffsets {
    double sum = 0.0;
    std::size_t n = 0;
  };
  template <class Direction>
  [[nodiscard]] SquaredOffsets squared_offsets(std::span<const int> members, const Direction& direction) const noexcept;
  /// RMS over `members` (those whose paint's direction is known; none: infinity) of the tangent
  /// of the angle, in the picture, between their paint and the ground direction (dx, dy).
  [[nodiscard]] double paint_rms(double dx, double dy, std::span<const int> members) const noexcept;
  /// RMS over `members` of the tangent of the angle, in the picture, between their paint and
  /// the circle's tangent.
  [[nodiscard]] double tangent_rms(const CentreCircle& c, std::span<const int> members) const noexcept;
  [[nodiscard]] PaintOffset paint_offset(double hx, double hy, int p) const noexcept {
    return vision::paint_offset(scratch_.along_[static_cast<std::size_t>(p)], scratch_.across_[static_cast<std::size_t>(p)],
                                hx, hy);
  }
  /// Point p's paint runs within atan(max_tan) of l in the picture (or its direction is unknown).
  [[nodiscard]] bool along_paint(const Line2& l, int p, double max_tan) const noexcept {
    return along_paint(l.dx, l.dy, p, max_tan);
  }
  /// The same for the ground direction (hx, hy), of any length.
  [[nodiscard]] bool along_paint(double hx, double hy, int p, double max_tan) const noexcept {
    return paint_runs_along(scratch_.along_[static_cast<std::size_t>(p)], scratch_.across_[static_cast<std::size_t>(p)],
                            hx, hy, max_tan);
  }
  /// The arc test of one piece; true (and the circle updated) when it is part of the circle.
  bool try_circle(const Line2& line, std::span<const int> piece, LineSet& out) noexcept;
  /// The support the piece [t0, t1] of `line` needs: thin_min_support where its paint is thin in
  /// the picture at its middle (the check knows the paint's width; without one, min_support).
  [[nodiscard]] double min_support(const Line2& line, double t0, double t1, const LineCheck* check) const noexcept;
  /// Emits the line's gap-free pieces (arcs go to the circle instead); true if any was emitted.
  bool add_pieces(const Line2& line, const hal::CameraIntrinsics& k, const hal::CameraPose& pose, int scan_stride,
                  const LineCheck* check, LineSet& out) noexcept;
  void merge(LineSet& out, const hal::CameraIntrinsics& k, const hal::CameraPose& pose, const LineCheck* check) const noexcept;
  /// Drops the pieces the picture's edge cuts that are shorter than min_cut_piece_px in the
  /// picture (none when the frame's circle is known).
  void drop_cut_short(LineSet& out, const hal::CameraIntrinsics& k) const noexcept;
  /// Drops the reported pieces that lie on the frame's circle (found by a later round).
  void drop_on_circle(LineSet& out) const noexcept;
  /// Drops the pieces whose nearer end lies farther than max_range_m.
  void drop_beyond_field(LineSet& out) const noexcept;
  void remove_from_pool(std::span<const int> members) noexcept;

  RansacParams params_;
  RansacScratch scratch_;
  double max_direction_tan_;    // tan(max_direction_deg), < 0: no gate
  double max_tangent_rms_tan_;  // tan(tangent_max_rms_deg)
};

}  // namespace ringlet::vision
