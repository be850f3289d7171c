#pragma once
// The known field: the SPL field's lines, centre circle, penalty marks and goal posts, built from
// a handful of dimensions so that a lab's smaller field is one configuration away. Field frame:
// origin at the centre spot, x along the long axis (the goals at x = ±length/2), y across; every
// straight line of an SPL field is parallel to x or to y, which the observation model uses to
// compare only lines of a compatible direction (B-Human's and HULKs' line models do the same).
#include <array>
#include <cstddef>
#include <span>
#include <string>

namespace ringlet::localization {

/// The dimensions of a field (m). Defaults: the SPL rule book's 9 m × 6 m field.
struct FieldDimensions {
  double length = 9.0;                 // between the goal lines
  double width = 6.0;                  // between the touch lines
  double centre_circle_radius = 0.75;
  double penalty_area_length = 1.65;   // from the goal line into the field
  double penalty_area_width = 4.0;
  double goal_area_length = 0.6;
  double goal_area_width = 2.2;
  double penalty_mark_distance = 1.3;  // from the goal line
  double goal_inner_width = 1.5;       // between the posts
  double border = 0.7;                 // carpet beyond the lines, where a robot may still stand
};

/// Empty when the dimensions make a field (positive, each area inside the next), else what is
/// wrong, naming the key as [field] spells it.
[[nodiscard]] std::string check(const FieldDimensions& d);

/// A straight field line (centre of the paint), parallel to x or to y: lo ≤ hi along its axis.
struct FieldLine {
  double at = 0.0;   // y of a line along x, x of a line along y
  double lo = 0.0;   // its extent along its own axis
  double hi = 0.0;
};

struct FieldPoint {
  double x = 0.0;
  double y = 0.0;
};

class FieldModel {
 public:
  static constexpr std::size_t kMaxLinesPerAxis = 12;

  explicit FieldModel(const FieldDimensions& d = {}) noexcept;

  [[nodiscard]] const FieldDimensions& dimensions() const noexcept { return dims_; }
  /// Touch lines, penalty and goal area sides.
  [[nodiscard]] std::span<const FieldLine> along_x() const noexcept { return {x_lines_.data(), x_count_}; }
  /// Goal lines, the centre line, penalty and goal area fronts.
  [[nodiscard]] std::span<const FieldLine> along_y() const noexcept { return {y_lines_.data(), y_count_}; }
  [[nodiscard]] double circle_radius() const noexcept { return dims_.centre_circle_radius; }
  [[nodiscard]] std::span<const FieldPoint, 2> penalty_marks() const noexcept { return penalty_marks_; }
  [[nodiscard]] std::span<const FieldPoint, 4> goal_posts() const noexcept { return goal_posts_; }

  /// Squared distance (m²) from (x, y) to the nearest line along x / along y.
  [[nodiscard]] double squared_distance_along_x(double x, double y) const noexcept;
  [[nodiscard]] double squared_distance_along_y(double x, double y) const noexcept;
  /// Inside the carpet: the lines plus the border, where a robot can be.
  [[nodiscard]] bool on_carpet(double x, double y) const noexcept;

 private:
  FieldDimensions dims_;
  std::array<FieldLine, kMaxLinesPerAxis> x_lines_{};
  std::array<FieldLine, kMaxLinesPerAxis> y_lines_{};
  std::size_t x_count_ = 0;
  std::size_t y_count_ = 0;
  std::array<FieldPoint, 2> penalty_marks_{};
  std::array<FieldPoint, 4> goal_posts_{};
};

}  // namespace ringlet::localization
