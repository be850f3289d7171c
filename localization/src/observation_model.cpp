#include "ringlet/localization/observation_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ringlet::localization {

void PreparedObservations::prepare(const Observations& obs, const ObservationParams& params) noexcept {
  point_count_ = 0;
  segment_count_ = 0;
  const double max_range2 = params.max_range * params.max_range;
  for (std::size_t i = 0; i < std::min(obs.line_count, Observations::kMaxLines); ++i) {
    const LineObservation& l = obs.lines[i];
    const double dx = l.x1 - l.x0;
    const double dy = l.y1 - l.y0;
    const double length = std::sqrt(dx * dx + dy * dy);
    if (!std::isfinite(length) || length < params.min_line_length) continue;
    // Points every half metre or so, ends included: 2 for a short piece, at most kPointsPerLine.
    const std::size_t n = std::clamp<std::size_t>(static_cast<std::size_t>(length / 0.5) + 2, 2, kPointsPerLine);
    const std::size_t seg = segment_count_;
    const std::size_t first = point_count_;
    std::size_t kept = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double t = static_cast<double>(k) / static_cast<double>(n - 1);
      const double px = l.x0 + t * dx;
      const double py = l.y0 + t * dy;
      const double r2 = px * px + py * py;
      if (r2 > max_range2) continue;
      const double sigma = params.line_sigma + params.line_sigma_per_m * std::sqrt(r2);
      points_[point_count_++] = {px, py, 1.0 / (sigma * sigma), static_cast<std::uint8_t>(seg)};
      ++kept;
    }
    if (kept == 0) continue;
    segments_[seg] = l;
    first_point_[seg] = first;
    point_counts_[seg] = kept;
    dir_x_[seg] = dx / length;
    dir_y_[seg] = dy / length;
    ++segment_count_;
  }
  circle_seen_ = obs.circle_seen && std::isfinite(obs.circle_x) && std::isfinite(obs.circle_y) &&
                 obs.circle_x * obs.circle_x + obs.circle_y * obs.circle_y <= max_range2;
  circle_x_ = obs.circle_x;
  circle_y_ = obs.circle_y;
}

ObservationModel::ObservationModel(const FieldModel& field, const ObservationParams& params) noexcept
    : field_(field), params_(params), circle_inv_sigma2_(1.0 / (params.circle_sigma * params.circle_sigma)) {
  // A direction at angle a from x has |dx| = |cos a|; within the tolerance of 45° it is diagonal.
  const double tol = params.diagonal_tolerance_deg * std::numbers::pi / 180.0;
  diagonal_lo_ = std::cos(std::numbers::pi / 4 + tol);
  diagonal_hi_ = std::cos(std::numbers::pi / 4 - tol);
}

double ObservationModel::term(double squared_error, double inv_sigma2) const noexcept {
  return 1.0 / (1.0 + squared_error * inv_sigma2);
}

double ObservationModel::line_error2(double wx, double wy, double dx) const noexcept {
  const double ax = std::fabs(dx);
  if (ax > diagonal_hi_) return field_.squared_distance_along_x(wx, wy);
  if (ax < diagonal_lo_) return field_.squared_distance_along_y(wx, wy);
  return std::min(field_.squared_distance_along_x(wx, wy), field_.squared_distance_along_y(wx, wy));
}

Fit ObservationModel::evaluate(const PreparedObservations& obs, const hal::Pose2& pose) const noexcept {
  // The points of one segment are not independent evidence (one line, one fit): a segment scores
  // the mean of its points' terms, floored, and the segments multiply.
  const hal::RobotToWorld to_world(pose);
  Fit fit;
  double sum = 0.0;
  for (std::size_t k = 0; k < obs.segment_count_; ++k) {
    const double wdx = to_world.direction(obs.dir_x_[k], obs.dir_y_[k]).x;  // the segment's world direction, x part
    double seg = 0.0;
    const std::size_t end = obs.first_point_[k] + obs.point_counts_[k];
    for (std::size_t i = obs.first_point_[k]; i < end; ++i) {
      const ObservedPoint& p = obs.points_[i];
      const hal::WorldPoint w = to_world.point(p.x, p.y);
      seg += term(line_error2(w.x, w.y, wdx), p.inv_sigma2);
    }
    const double t = std::max(params_.min_term, seg / static_cast<double>(obs.point_counts_[k]));
    fit.likelihood *= t;
    sum += t;
  }
  fit.terms = obs.segment_count_;
  if (obs.circle_seen_) {
    const hal::WorldPoint w = to_world.point(obs.circle_x_, obs.circle_y_);
    const double t = term(circle_error2(w.x, w.y), circle_inv_sigma2_);
    for (int k = 0; k < params_.circle_terms; ++k) {
      fit.likelihood *= t;
      sum += t;
    }
    fit.terms += static_cast<std::size_t>(params_.circle_terms);
  }
  fit.quality = fit.terms == 0 ? 0.0 : sum / static_cast<double>(fit.terms);
  return fit;
}

}  // namespace ringlet::localization
