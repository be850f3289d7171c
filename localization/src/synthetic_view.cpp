#include "ringlet/localization/synthetic_view.hpp"

#include <cmath>

#include "ringlet/hal/portable_math.hpp"
#include "ringlet/localization/gaussian.hpp"

namespace ringlet::localization {
namespace {

constexpr double kStep = 0.05;  // m between the sampled points of a field line

bool visible(const hal::RobotPoint& p, const ViewParams& v) noexcept {
  const double r = std::sqrt(p.x * p.x + p.y * p.y);
  if (r < v.min_range || r > v.max_range) return false;
  return std::fabs(hal::wrap_angle(hal::portable_atan2(p.y, p.x) - v.head_yaw)) <= v.half_fov;
}

// Adds the visible runs of the world line (x0, y0)–(x1, y1) as robot-frame segments.
void add_visible(Observations& obs, const hal::Pose2& truth, const ViewParams& v, double x0, double y0, double x1,
                 double y1, hal::SplitMix64& rng) {
  const double len = hal::portable_hypot(x1 - x0, y1 - y0);
  const auto n = static_cast<int>(len / kStep) + 1;
  bool in_run = false;
  hal::RobotPoint first{}, last{};
  const auto close_run = [&] {
    if (!in_run) return;
    in_run = false;
    if (hal::portable_hypot(last.x - first.x, last.y - first.y) < 0.3) return;
    if (uniform(rng) < v.drop) return;
    const auto jitter = [&](hal::RobotPoint p) {
      const double s = v.noise + v.noise_per_m * hal::portable_hypot(p.x, p.y);
      return hal::RobotPoint{p.x + s * standard_normal(rng), p.y + s * standard_normal(rng)};
    };
    const hal::RobotPoint a = jitter(first);
    const hal::RobotPoint b = jitter(last);
    obs.add_line({a.x, a.y, b.x, b.y});
  };
  for (int i = 0; i <= n; ++i) {
    const double t = std::fmin(1.0, static_cast<double>(i) * kStep / len);
    const hal::RobotPoint p = hal::to_robot_frame(truth, x0 + t * (x1 - x0), y0 + t * (y1 - y0));
    if (visible(p, v)) {
      if (!in_run) first = p;
      last = p;
      in_run = true;
    } else {
      close_run();
    }
  }
  close_run();
}

}  // namespace

Observations synthetic_view(const FieldModel& field, const hal::Pose2& truth, const ViewParams& v,
                            hal::SplitMix64& rng) noexcept {
  Observations obs;
  for (const FieldLine& l : field.along_x()) add_visible(obs, truth, v, l.lo, l.at, l.hi, l.at, rng);
  for (const FieldLine& l : field.along_y()) add_visible(obs, truth, v, l.at, l.lo, l.at, l.hi, rng);
  // The circle: seen when at least a third of its rim is in view (vision fits it from an arc).
  int rim_visible = 0;
  constexpr int kRim = 24;
  for (int k = 0; k < kRim; ++k) {
    const double a = 2.0 * 3.141592653589793 * k / kRim;
    const double r = field.circle_radius();
    if (visible(hal::to_robot_frame(truth, r * std::cos(a), r * std::sin(a)), v)) ++rim_visible;
  }
  if (rim_visible * 3 >= kRim) {
    const hal::RobotPoint c = hal::to_robot_frame(truth, 0.0, 0.0);
    const double s = v.noise + v.noise_per_m * hal::portable_hypot(c.x, c.y);
    obs.circle_seen = true;
    obs.circle_x = c.x + s * standard_normal(rng);
    obs.circle_y = c.y + s * standard_normal(rng);
  }
  if (uniform(rng) < v.false_line) {
    // A short false segment somewhere in view, in a random direction (a leg, a shadow edge).
    const double r = v.min_range + uniform(rng) * (v.max_range - v.min_range);
    const double a = v.head_yaw + (2.0 * uniform(rng) - 1.0) * v.half_fov;
    const double d = (2.0 * uniform(rng) - 1.0) * 3.141592653589793;
    const double px = r * std::cos(a);
    const double py = r * std::sin(a);
    obs.add_line({px, py, px + 0.6 * std::cos(d), py + 0.6 * std::sin(d)});
  }
  return obs;
}

}  // namespace ringlet::localization
