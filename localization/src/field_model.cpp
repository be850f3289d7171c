#include "ringlet/localization/field_model.hpp"

#include <cmath>
#include <limits>

namespace ringlet::localization {
namespace {

// Squared distance from the point (along, across) to a line at `across = l.at` from lo to hi.
double squared_distance(const FieldLine& l, double along, double across) noexcept {
  const double d_across = across - l.at;
  const double d_along = along < l.lo ? l.lo - along : (along > l.hi ? along - l.hi : 0.0);
  return d_across * d_across + d_along * d_along;
}

}  // namespace

std::string check(const FieldDimensions& d) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(d.length)) return "length must be a positive number of metres";
  if (!positive(d.width)) return "width must be a positive number of metres";
  if (!positive(d.centre_circle_radius) || 2.0 * d.centre_circle_radius >= d.width)
    return "centre_circle_radius must be positive and the circle narrower than the field";
  if (!positive(d.penalty_area_length) || 2.0 * d.penalty_area_length >= d.length)
    return "penalty_area_length must be positive and less than half the length";
  if (!positive(d.penalty_area_width) || d.penalty_area_width >= d.width)
    return "penalty_area_width must be positive and less than the width";
  if (!positive(d.goal_area_length) || d.goal_area_length >= d.penalty_area_length)
    return "goal_area_length must be positive and less than penalty_area_length";
  if (!positive(d.goal_area_width) || d.goal_area_width >= d.penalty_area_width)
    return "goal_area_width must be positive and less than penalty_area_width";
  if (!positive(d.penalty_mark_distance) || d.penalty_mark_distance >= 0.5 * d.length)
    return "penalty_mark_distance must be positive and less than half the length";
  if (!positive(d.goal_inner_width) || d.goal_inner_width >= d.width)
    return "goal_inner_width must be positive and less than the width";
  if (!std::isfinite(d.border) || d.border < 0.0) return "border must be a non-negative number of metres";
  return {};
}

FieldModel::FieldModel(const FieldDimensions& d) noexcept : dims_(d) {
  const double hl = 0.5 * d.length;
  const double hw = 0.5 * d.width;
  const double pw = 0.5 * d.penalty_area_width;
  const double gw = 0.5 * d.goal_area_width;
  const double pf = hl - d.penalty_area_length;  // |x| of a penalty area's front line
  const double gf = hl - d.goal_area_length;
  const auto along_x = [this](double y, double x0, double x1) { x_lines_[x_count_++] = {y, x0, x1}; };
  const auto along_y = [this](double x, double y0, double y1) { y_lines_[y_count_++] = {x, y0, y1}; };
  along_x(-hw, -hl, hl);  // touch lines
  along_x(hw, -hl, hl);
  along_y(-hl, -hw, hw);  // goal lines
  along_y(hl, -hw, hw);
  along_y(0.0, -hw, hw);  // centre line
  for (const double side : {-1.0, 1.0}) {
    const double goal = side * hl;
    const double pen = side * pf;
    const double gar = side * gf;
    along_x(-pw, std::fmin(goal, pen), std::fmax(goal, pen));  // penalty area sides
    along_x(pw, std::fmin(goal, pen), std::fmax(goal, pen));
    along_y(pen, -pw, pw);                                      // penalty area front
    along_x(-gw, std::fmin(goal, gar), std::fmax(goal, gar));  // goal area sides
    along_x(gw, std::fmin(goal, gar), std::fmax(goal, gar));
    along_y(gar, -gw, gw);                                      // goal area front
  }
  penalty_marks_ = {FieldPoint{-(hl - d.penalty_mark_distance), 0.0}, FieldPoint{hl - d.penalty_mark_distance, 0.0}};
  const double post = 0.5 * d.goal_inner_width;
  goal_posts_ = {FieldPoint{-hl, -post}, FieldPoint{-hl, post}, FieldPoint{hl, -post}, FieldPoint{hl, post}};
}

double FieldModel::squared_distance_along_x(double x, double y) const noexcept {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < x_count_; ++i) best = std::fmin(best, squared_distance(x_lines_[i], x, y));
  return best;
}

double FieldModel::squared_distance_along_y(double x, double y) const noexcept {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < y_count_; ++i) best = std::fmin(best, squared_distance(y_lines_[i], y, x));
  return best;
}

bool FieldModel::on_carpet(double x, double y) const noexcept {
  return std::fabs(x) <= 0.5 * dims_.length + dims_.border && std::fabs(y) <= 0.5 * dims_.width + dims_.border;
}

}  // namespace ringlet::localization
