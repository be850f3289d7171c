#pragma once
// The centre circle scored on its own, and line segments that are really pieces of it.
//
//   Truth: the frame's ring (ringlet-dataset's "rings": centre in the robot frame, radius, the
//   share of it that is visible). A ring is EXPECTED when at least min_visible_deg of it is
//   visible (visible share × 360°); less is "don't care" for recall.
//   A detected circle MATCHES a visible ring when its centre is within max_centre_error_m of the
//   ring's and its radius within max_radius_error_m. Precision: matching detections / detections
//   (a detection matching only a don't-care ring is neither right nor wrong); recall: expected
//   rings matched / expected rings. Errors (centre, radius) over the matches.
//
//   An ARC FALSE POSITIVE is a reported straight segment that matches no true straight segment
//   (segment_match.hpp's rule, today's tolerances) and lies along the projected ring: five points
//   spread along it are each within max_distance_px + the ring's projected half width of it.
//   Such detections were already false positives in the line precision; this counts them apart.
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "ringlet/hal/camera_geometry.hpp"
#include "segment_match.hpp"

namespace ringlet::vision::evaluate {

struct TruthRing {
  hal::RobotPoint centre{};  // robot frame
  double radius = 0.75;
  double width = 0.05;
  bool visible = false;
  double visible_fraction = 0.0;
};

struct CircleMatchParams {
  double max_centre_error_m = 0.25;
  double max_radius_error_m = 0.15;
  double min_visible_deg = 60.0;
};

struct DetectedCircle {
  bool seen = false;
  hal::RobotPoint centre{};
  double radius = 0.0;
};

/// Expected rings by the distance of their centre from the robot: bins from these distances (m),
/// the last one open. Far circles are a pixel or two of paint high: where recall is lost.
inline constexpr std::array<double, 4> kRingDistanceBinsM{0.0, 3.0, 4.0, 5.0};

struct CircleCounts {
  std::size_t detections = 0;      // scored detections
  std::size_t true_positives = 0;
  std::size_t truths = 0;          // expected rings
  std::size_t recalled = 0;
  double centre_error_sum_m = 0.0;  // over true positives
  double radius_error_sum_m = 0.0;
  std::array<std::size_t, kRingDistanceBinsM.size()> truths_by_distance{};  // score_circle only
  std::array<std::size_t, kRingDistanceBinsM.size()> recalled_by_distance{};

  CircleCounts& operator+=(const CircleCounts& o) noexcept;
  [[nodiscard]] double precision() const noexcept;
  [[nodiscard]] double recall() const noexcept;
  [[nodiscard]] double f1() const noexcept;
  [[nodiscard]] double mean_centre_error_m() const noexcept;
  [[nodiscard]] double mean_radius_error_m() const noexcept;
};

/// The kRingDistanceBinsM bin of a ring centred at `centre` (robot frame).
[[nodiscard]] std::size_t ring_distance_bin(const hal::RobotPoint& centre) noexcept;

/// One frame's detected circle (or none) against its rings.
[[nodiscard]] CircleCounts score_circle(const DetectedCircle& detected, std::span<const TruthRing> rings,
                                        const CircleMatchParams& params = {});

/// The ring's visible-or-not outline in the image: ground points every 0.5° projected (those
/// that project), with the ring's projected half width at each.
struct RingImage {
  std::vector<Segment2> pieces;       // between consecutive projected samples
  std::vector<double> half_width_px;  // per piece
};
[[nodiscard]] RingImage project_ring(const TruthRing& ring, const hal::CameraIntrinsics& k, const hal::CameraPose& pose);

/// Whether `segment` lies along `ring` (every one of 5 points within max_distance_px + half width).
[[nodiscard]] bool lies_on_ring(const Segment2& segment, const RingImage& ring, double max_distance_px);

/// Detections that match no true straight segment and lie along a ring: arc pieces taken for lines.
[[nodiscard]] std::size_t count_arc_false_positives(std::span<const Segment2> detected, std::span<const TruthSegment> truth,
                                                    std::span<const RingImage> rings, const MatchParams& match = {});

}  // namespace ringlet::vision::evaluate
