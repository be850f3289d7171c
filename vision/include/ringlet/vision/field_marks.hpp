#pragma once
// The penalty marks and the centre mark: small painted crosses (SPL: two 100 mm bars, 50 mm wide,
// along the field's axes), landmarks a localisation can use on their own. RANSAC does not find
// them (a 10 cm bar is shorter than any line it reports), and if it did, a cross would be two
// "lines" of no use to anyone.
//
// Found from what the line stage leaves over, then checked in the picture:
//   1. Candidates farther than `line_clearance_m` from every reported line, off the centre circle's
//      band, away from balls and within `max_range_m` (at most `max_points` of them: bounded cost).
//   2. A cluster: at least `min_points` of them within `cluster_radius_m` (plus the range error of
//      `range_rows` image rows, far marks' points scatter in range) of one of them, refitted once
//      around its centroid, with at most `max_ring_points` more out to `clear_radius_m`: a cross
//      stands alone on the carpet, clutter (robots, the goal, a net) does not.
//   3. The picture: at 12 points on the ground circle of `clear_radius_m` the class is
//      field (a ball, a foot or a line crossing reaches it), and a cross fits: of the orientations
//      0°, 5°, ... 85°, the one whose two bars' samples look most like paint and whose four gaps
//      between the arms look most like field; its share of agreeing samples is the confidence.
// Cost: the clearance tests (points × lines), the cluster distances (≤ 3 × max_points²), and per
// cluster 12 + 144 + 13 projections and class reads, all counted in `tests`; the deadline is
// checked before each cluster.
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/vision/ball.hpp"
#include "ringlet/vision/centre_circle.hpp"
#include "ringlet/vision/class_image.hpp"
#include "ringlet/vision/deadline.hpp"
#include "ringlet/vision/ransac.hpp"
#include "ringlet/vision/scan_points.hpp"

namespace ringlet::vision {

inline constexpr std::size_t kMaxFieldMarks = 2;

struct FieldMarkParams {
  bool enabled = true;
  double bar_length_m = 0.10;     // each bar of the cross
  double bar_width_m = 0.05;
  double max_range_m = 5.0;       // farther, a cross is a few pixels: not told from a speck
  double line_clearance_m = 0.15; // candidates this near a reported line belong to it
  double ball_clearance_m = 0.25; // ... this near a ball, to the ball
  double circle_band_m = 0.15;    // ... this near the centre circle, to the circle
  double cluster_radius_m = 0.09; // the cross's points around its centre (half its diagonal + slack)
  double range_rows = 1.5;        // plus this many image rows of range error (far marks)
  int min_points = 4;
  double clear_radius_m = 0.30;   // nothing but carpet out to here
  int max_ring_points = 1;        // leftover candidates allowed between the cluster and that ring
  double min_ring_field = 0.8;    // share of the ring's samples in the picture that must be field
  double min_confidence = 0.9;    // share of the cross's samples that must agree
  int max_points = 128;           // leftover candidates examined (≤ 3 × max_points² distance tests)
};

struct FieldMark {
  hal::RobotPoint centre{};       // robot frame, on the ground
  double orientation_rad = 0.0;   // one bar's direction in the robot frame, in [0, π/2)
  double confidence = 0.0;        // share of the cross's samples that look as a cross should
  int points = 0;                 // scan candidates on it
  double distance_m = 0.0;
  double bearing_rad = 0.0;       // atan2(y, x) of the centre: positive to the left
};

struct FieldMarkList {
  std::array<FieldMark, kMaxFieldMarks> marks{};
  std::size_t count = 0;
  int leftovers = 0;       // candidates examined (after the clearances, at most max_points)
  int clusters = 0;        // clusters judged in the picture
  int rejected = 0;        // clusters the picture did not show as a lone cross
  std::int64_t tests = 0;  // distance tests, projections and class reads: work for the cost model
  bool stopped_early = false;  // the deadline passed before every cluster was looked at
};

class FieldMarkFinder {
 public:
  /// Allocates its scratch for `capacity` candidates (max_points of them are ever used).
  FieldMarkFinder(const FieldMarkParams& params, std::size_t capacity);

  /// The crosses among the candidates the lines, the circle and the balls leave over. It stops
  /// (`out.stopped_early`) when `deadline` has passed before a cluster, or before a step whose
  /// tests could take `out.tests` past `max_tests` (the pipeline's share of a modelled budget):
  /// a candidate's at most one per line, a cluster's at most 3 × leftovers + a judgement's.
  void find(std::span<const CandidatePoint> candidates, std::span<const FieldLine> lines, const CentreCircle& circle,
            std::span<const BallDetection> balls, const ClassImage& classes, const hal::CameraIntrinsics& k,
            const hal::CameraPose& pose, const Deadline& deadline, FieldMarkList& out,
            std::int64_t max_tests = std::numeric_limits<std::int64_t>::max()) noexcept;

  /// The two bars of `mark` as ground segments (for drawing and scoring).
  [[nodiscard]] static std::array<std::array<hal::RobotPoint, 2>, 2> bars(const FieldMark& mark,
                                                                         double bar_length_m = 0.10) noexcept;

  [[nodiscard]] const FieldMarkParams& params() const noexcept { return params_; }

 private:
  // The radius around `p` that holds a cross's points: cluster_radius_m plus the range error.
  [[nodiscard]] double cluster_radius(const hal::RobotPoint& p, const hal::CameraIntrinsics& k,
                                      const hal::CameraPose& pose) const noexcept;
  // Judges a cluster centred at `c` in the picture; fills orientation and confidence, true when
  // it is a lone cross.
  bool judge(const hal::RobotPoint& c, const ClassImage& classes, const hal::CameraIntrinsics& k,
             const hal::CameraPose& pose, FieldMark& mark, std::int64_t& tests) const noexcept;

  FieldMarkParams params_;
  std::size_t limit_;                  // leftovers examined at most
  std::vector<hal::RobotPoint> left_;  // leftover candidates' ground points
  std::vector<std::uint8_t> taken_;    // per leftover: already part of a judged cluster
};

}  // namespace ringlet::vision
