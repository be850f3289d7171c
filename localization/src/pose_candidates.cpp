#include "ringlet/localization/pose_candidates.hpp"

#include <cmath>
#include <numbers>

#include "ringlet/hal/portable_math.hpp"

#include "ringlet/localization/gaussian.hpp"

namespace ringlet::localization {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMinSegment = 0.5;       // m: shorter segments give too loose a heading
constexpr double kThroughCircle = 0.35;   // m: a line this close to the circle's centre is the centre line

// The robot pose that puts robot-frame point (px, py) at world (wx, wy) with heading theta.
hal::Pose2 placing(double px, double py, double wx, double wy, double theta) noexcept {
  const hal::WorldPoint offset = hal::RobotToWorld(hal::Pose2{0.0, 0.0, theta}).direction(px, py);
  return {wx - offset.x, wy - offset.y, hal::wrap_angle(theta)};
}

// The heading under which a robot-frame direction (dx, dy) points along world +y, and along +x.
double heading_along_y(double dx, double dy) noexcept { return hal::portable_atan2(dy, dx); }
double heading_along_x(double dx, double dy) noexcept { return hal::portable_atan2(dx, -dy); }

// Distance of the point (cx, cy) from the infinite line through a segment.
double distance_to_line(const LineObservation& l, double cx, double cy) noexcept {
  const double dx = l.x1 - l.x0;
  const double dy = l.y1 - l.y0;
  const double len = std::sqrt(dx * dx + dy * dy);
  return std::fabs((cx - l.x0) * dy - (cy - l.y0) * dx) / len;
}

double length(const LineObservation& l) noexcept {
  const double dx = l.x1 - l.x0;
  const double dy = l.y1 - l.y0;
  return std::sqrt(dx * dx + dy * dy);
}

bool from_circle(const PreparedObservations& obs, hal::SplitMix64& rng, hal::Pose2& out) noexcept {
  const double cx = obs.circle_x();
  const double cy = obs.circle_y();
  double theta = (2.0 * uniform(rng) - 1.0) * kPi;
  for (std::size_t i = 0; i < obs.segment_count(); ++i) {
    const LineObservation& l = obs.segment(i);
    if (length(l) >= kMinSegment && distance_to_line(l, cx, cy) < kThroughCircle) {
      theta = heading_along_y(l.x1 - l.x0, l.y1 - l.y0);  // the centre line runs along y
      break;
    }
  }
  out = placing(cx, cy, 0.0, 0.0, theta);
  return true;
}

bool from_segment(const PreparedObservations& obs, const FieldModel& field, hal::SplitMix64& rng,
                  hal::Pose2& out) noexcept {
  const LineObservation& l = obs.segment(static_cast<std::size_t>(rng.below(obs.segment_count())));
  if (length(l) < kMinSegment) return false;
  const double mx = 0.5 * (l.x0 + l.x1);
  const double my = 0.5 * (l.y0 + l.y1);
  const double flip = rng.below(2) == 0 ? 0.0 : kPi;  // which way along the field line it runs
  const std::size_t nx = field.along_x().size();
  const std::size_t k = static_cast<std::size_t>(rng.below(nx + field.along_y().size()));
  const double u = uniform(rng);
  if (k < nx) {
    const FieldLine& f = field.along_x()[k];
    out = placing(mx, my, f.lo + u * (f.hi - f.lo), f.at, heading_along_x(l.x1 - l.x0, l.y1 - l.y0) + flip);
  } else {
    const FieldLine& f = field.along_y()[k - nx];
    out = placing(mx, my, f.at, f.lo + u * (f.hi - f.lo), heading_along_y(l.x1 - l.x0, l.y1 - l.y0) + flip);
  }
  return field.on_carpet(out.x, out.y);
}

}  // namespace

hal::Pose2 uniform_pose(const FieldModel& field, hal::SplitMix64& rng, double x_sign) noexcept {
  const FieldDimensions& d = field.dimensions();
  const double hx = 0.5 * d.length + d.border;
  const double hy = 0.5 * d.width + d.border;
  double x = (2.0 * uniform(rng) - 1.0) * hx;
  if (x_sign != 0.0) x = std::copysign(std::fabs(x), x_sign);
  const double y = (2.0 * uniform(rng) - 1.0) * hy;
  return {x, y, (2.0 * uniform(rng) - 1.0) * kPi};
}

std::size_t pose_candidates(const PreparedObservations& obs, const FieldModel& field, hal::SplitMix64& rng,
                            std::span<hal::Pose2> out) noexcept {
  std::size_t n = 0;
  // A few tries per pair: a segment laid on a short line far from the robot can land off the carpet.
  for (std::size_t tries = 0; n + 2 <= out.size() && tries < 2 * out.size(); ++tries) {
    hal::Pose2 p{};
    bool ok = false;
    if (obs.circle_seen() && (obs.segment_count() == 0 || rng.below(2) == 0)) {
      ok = from_circle(obs, rng, p);
    } else if (obs.segment_count() > 0) {
      ok = from_segment(obs, field, rng, p);
    } else {
      p = uniform_pose(field, rng);
      ok = true;
    }
    if (!ok) continue;
    out[n++] = p;
    out[n++] = mirrored(p);
  }
  return n;
}

}  // namespace ringlet::localization
