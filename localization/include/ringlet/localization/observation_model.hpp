#pragma once
// How well a pose explains what vision saw: each observed ground segment is sampled at a few
// points, each point is taken to the field under the pose and compared with the nearest field line
// of the segment's direction (along x or along y), and the circle's centre with the centre spot.
// An error e (m) scores a Cauchy term 1 / (1 + (e/σ)²), σ growing with the point's range; a
// segment scores the mean of its points' terms, at least min_term, and the segments multiply: one
// false line (a robot's leg, a line vision joined across two) costs at most a factor 1/min_term
// instead of vetoing the right pose, which a Gaussian would. Only + − × ÷ and sin/cos of the pose: the same
// bits on x86-64 and aarch64 (the build has -ffp-contract=off).
#include <array>
#include <cstddef>
#include <cstdint>

#include "ringlet/hal/geometry.hpp"
#include "ringlet/localization/field_model.hpp"
#include "ringlet/localization/observations.hpp"

namespace ringlet::localization {

struct ObservationParams {
  double line_sigma = 0.12;             // m, at the robot
  double line_sigma_per_m = 0.06;       // m more per metre of range (the ground projection's error grows)
  double min_line_length = 0.3;         // m: shorter segments are left out (mostly noise)
  double max_range = 6.0;               // m: farther points are left out
  double diagonal_tolerance_deg = 20.0; // a segment this close to 45° is compared with both directions
  double circle_sigma = 0.25;           // m, the circle centre's error
  int circle_terms = 2;                 // the circle counts as this many segments (it fixes x and y)
  double min_term = 0.1;                // floor of a segment's term: it costs at most a factor of 10
};

/// One point of an observed segment, prepared once per observation set.
struct ObservedPoint {
  double x = 0.0, y = 0.0;  // robot frame
  double inv_sigma2 = 0.0;  // 1 / σ² at its range
  std::uint8_t segment = 0;
};

/// The observation set turned into sample points, each segment's robot-frame direction.
class PreparedObservations {
 public:
  static constexpr std::size_t kPointsPerLine = 5;
  static constexpr std::size_t kMaxPoints = Observations::kMaxLines * kPointsPerLine;

  void prepare(const Observations& obs, const ObservationParams& params) noexcept;

  [[nodiscard]] std::size_t point_count() const noexcept { return point_count_; }
  [[nodiscard]] const ObservedPoint& point(std::size_t i) const noexcept { return points_[i]; }
  [[nodiscard]] std::size_t segment_count() const noexcept { return segment_count_; }
  [[nodiscard]] const LineObservation& segment(std::size_t i) const noexcept { return segments_[i]; }
  [[nodiscard]] bool circle_seen() const noexcept { return circle_seen_; }
  [[nodiscard]] double circle_x() const noexcept { return circle_x_; }
  [[nodiscard]] double circle_y() const noexcept { return circle_y_; }
  [[nodiscard]] bool empty() const noexcept { return point_count_ == 0 && !circle_seen_; }
  /// Point terms one evaluation computes (the work the cost model counts): the segments' points
  /// plus the circle.
  [[nodiscard]] std::size_t work(const ObservationParams& /*params*/) const noexcept {
    return point_count_ + (circle_seen_ ? 1 : 0);
  }

 private:
  std::array<ObservedPoint, kMaxPoints> points_{};
  std::array<LineObservation, Observations::kMaxLines> segments_{};
  std::array<double, Observations::kMaxLines> dir_x_{}, dir_y_{};  // unit direction, robot frame
  std::array<std::size_t, Observations::kMaxLines> first_point_{}, point_counts_{};
  std::size_t point_count_ = 0;
  std::size_t segment_count_ = 0;
  bool circle_seen_ = false;
  double circle_x_ = 0.0, circle_y_ = 0.0;

  friend class ObservationModel;
};

/// The fit of one pose: the product of its terms, one per segment and circle_terms for the circle
/// (the particle weight's factor), and their mean (a quality in (0, 1] whatever the number of
/// terms: 1 is a perfect fit).
struct Fit {
  double likelihood = 1.0;
  double quality = 0.0;
  std::size_t terms = 0;
};

class ObservationModel {
 public:
  ObservationModel(const FieldModel& field, const ObservationParams& params) noexcept;

  /// The Cauchy term of an error of e² (m²) against 1/σ² (unfloored: the floor is per segment).
  [[nodiscard]] double term(double squared_error, double inv_sigma2) const noexcept;
  /// Squared distance (m²) from the world point (wx, wy) to the nearest field line of a segment
  /// whose unit world direction has x component dx: along x, along y, or the nearer of both for
  /// a diagonal segment.
  [[nodiscard]] double line_error2(double wx, double wy, double dx) const noexcept;
  /// Squared distance (m²) of a world point from the centre spot: the circle's error.
  [[nodiscard]] static double circle_error2(double wx, double wy) noexcept { return wx * wx + wy * wy; }

  /// The fit of `pose` (hal convention: heading from +y towards +x) to the prepared observations.
  [[nodiscard]] Fit evaluate(const PreparedObservations& obs, const hal::Pose2& pose) const noexcept;

  [[nodiscard]] const ObservationParams& params() const noexcept { return params_; }
  [[nodiscard]] const FieldModel& field() const noexcept { return field_; }

 private:
  const FieldModel& field_;
  ObservationParams params_;
  double diagonal_lo_, diagonal_hi_;  // |dx| of a direction diagonal_tolerance either side of 45°
  double circle_inv_sigma2_;
};

}  // namespace ringlet::localization
