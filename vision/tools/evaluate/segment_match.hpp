#pragma once
// How detected line segments are scored against ground truth, the same way for every detector
// (Ringlet's RANSAC pipeline and Canny + HoughLinesP), in image coordinates (pixels):
//
//   A painted line seen past an occluder (the ball, a robot's legs, a goal post) is several true
//   segments of one marking; the marking's VISIBLE EXTENT is the segment between its two farthest
//   visible ends. A detection MATCHES a marking when the acute angle to that extent is at most
//   max_angle_deg and both of its endpoints lie within max_distance_px plus the line's half width
//   in the image (a painted line is a band: an edge detector finds its borders, a centre-line
//   detector its middle; both are right) of it: a fit straight through the ball is the same line,
//   not a false positive. (Segments without a marking, -1, are markings of their own.)
//   Its projection then covers each of the marking's true segments.
//   Precision: detections that match some marking / all detections.
//   Recall: true segments whose length is covered to at least min_coverage by the projections of
//   the detections matching them / all true segments. Several fragments may cover one segment;
//   fragments are not punished in precision, but only coverage earns recall.
//   True segments shorter than min_truth_length_px are "don't care": not counted for recall,
//   and a detection matching only such segments is neither right nor wrong (left out).
//   Errors over matching detections: angle (degrees), endpoint distance to the true segment
//   (pixels); over recalled true segments: extent error, how far the covered interval's ends are
//   from the true segment's ends (pixels).
#include <cstddef>
#include <array>
#include <span>

namespace ringlet::vision::evaluate {

struct Segment2 {
  double x0 = 0.0;
  double y0 = 0.0;
  double x1 = 0.0;
  double y1 = 0.0;
};

/// A visible part of a painted line: its centre line in the image and half its width there
/// (the larger of its two ends).
struct TruthSegment {
  Segment2 line{};
  double half_width_px = 0.0;
  int marking = -1;  // which painted line this piece belongs to (ringlet-dataset "marking"); -1: unknown
};

struct MatchParams {
  double max_angle_deg = 5.0;
  double max_distance_px = 8.0;
  double min_coverage = 0.5;
  double min_truth_length_px = 20.0;
};

/// Recall is also counted by how wide the paint is in the picture (twice the truth's half width):
/// below 2 px, 2–4, 4–8 and from 8 px. Where the misses lie says what would help: far lines a pixel
/// or two wide need other evidence than near ones.
inline constexpr std::array<double, 4> kWidthBucketsPx{0.0, 2.0, 4.0, 8.0};
[[nodiscard]] std::size_t width_bucket(double half_width_px) noexcept;

struct MatchCounts {
  std::size_t detections = 0;       // scored detections (those matching only don't-care ones excluded)
  std::size_t true_positives = 0;   // scored detections that match a true segment
  std::size_t truths = 0;           // true segments counted for recall
  std::size_t recalled = 0;
  double angle_error_sum_deg = 0.0;     // over true positives
  double endpoint_error_sum_px = 0.0;   // over true positives (mean of their two endpoints)
  double extent_error_sum_px = 0.0;     // over recalled truths (mean of their two ends)
  std::array<std::size_t, kWidthBucketsPx.size()> truths_by_width{};    // truths, by width_bucket
  std::array<std::size_t, kWidthBucketsPx.size()> recalled_by_width{};  // recalled truths, by width_bucket

  MatchCounts& operator+=(const MatchCounts& o) noexcept;
  [[nodiscard]] double precision() const noexcept;
  [[nodiscard]] double recall() const noexcept;
  [[nodiscard]] double f1() const noexcept;
  [[nodiscard]] double mean_angle_error_deg() const noexcept;
  [[nodiscard]] double mean_endpoint_error_px() const noexcept;
  [[nodiscard]] double mean_extent_error_px() const noexcept;
};

[[nodiscard]] MatchCounts match_segments(std::span<const Segment2> detected, std::span<const TruthSegment> truth,
                                         const MatchParams& params = {});

}  // namespace ringlet::vision::evaluate
