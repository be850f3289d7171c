// A fitted piece checked against the class image (line_check.hpp).
#include "ringlet/vision/line_check.hpp"

#include <algorithm>
#include <cmath>

#include "ringlet/hal/portable_math.hpp"

namespace ringlet::vision {

bool LineCheck::outside(double x, double y) const noexcept {
  return x < 0.0 || y < 0.0 || x >= static_cast<double>(classes_.width()) || y >= static_cast<double>(classes_.height());
}

bool LineCheck::looks_like_line(double cx, double cy, double nx, double ny, double h) const noexcept {
  // The paint: a line pixel within half the band plus the slack of the fit.
  const int reach = static_cast<int>(std::ceil(h + params_.centre_slack_px));
  int centre = 0;
  bool on_paint = false;
  for (int d = 0; d <= reach && !on_paint; ++d) {
    for (const int sign : {1, -1}) {
      if (classes_.class_near(cx + sign * d * nx, cy + sign * d * ny) == ColourClass::kLine) {
        centre = sign * d;
        on_paint = true;
        break;
      }
    }
  }
  if (!on_paint) return false;
  // From there outwards on each side: the band ends within its allowed width, and the first
  // thing after it (past a blurred edge) is field.
  const int band = static_cast<int>(std::ceil(2.0 * h * params_.band_factor + params_.band_slack_px));
  for (const int sign : {1, -1}) {
    int d = centre;
    int steps = 0;
    while (steps <= band && classes_.class_near(cx + d * nx, cy + d * ny) == ColourClass::kLine) {
      d += sign;
      ++steps;
    }
    if (steps > band) return false;  // too wide for paint: a robot, a post, a white wall
    bool field = false;
    for (int e = 0; e <= params_.edge_px; ++e, d += sign) {
      if (outside(cx + d * nx, cy + d * ny)) {  // the picture's edge cut the band: nothing to say
        field = true;
        break;
      }
      const ColourClass c = classes_.class_near(cx + d * nx, cy + d * ny);
      if (c == ColourClass::kField) {
        field = true;
        break;
      }
      if (c == ColourClass::kLine) break;
    }
    if (!field) return false;
  }
  return true;
}

double LineCheck::half_width_px(const hal::RobotPoint& at, double dx, double dy) const noexcept {
  const auto c = hal::project(k_, pose_, {at.x, at.y, 0.0});
  return c ? half_width_from(*c, at, dx, dy) : 0.0;
}

double LineCheck::half_width_from(const hal::Pixel& c, const hal::RobotPoint& at, double dx, double dy) const noexcept {
  const double w = params_.line_width_m / 2.0;
  const auto e = hal::project(k_, pose_, {at.x - dy * w, at.y + dx * w, 0.0});
  if (!e) return 0.0;
  const double ex = e->u - c.u, ey = e->v - c.v;
  return std::sqrt(ex * ex + ey * ey);
}

int LineCheck::judge(const hal::RobotPoint& a, const hal::RobotPoint& b, int i, int n) const noexcept {
  const double gx = b.x - a.x, gy = b.y - a.y;
  const double len = std::sqrt(gx * gx + gy * gy);
  const double t = (static_cast<double>(i) + 0.5) / static_cast<double>(n);
  const double px = a.x + t * gx, py = a.y + t * gy;
  const auto c = hal::project(k_, pose_, {px, py, 0.0});
  if (!c) return -1;
  const double h = half_width_from(*c, {px, py}, gx / len, gy / len);
  if (h <= 0.0) return -1;
  if (c->u < 0.0 || c->u >= classes_.width() || c->v < classes_.first_row() || c->v >= classes_.height()) return -1;
  // The normal in the picture: across the projected line, i.e. perpendicular to its image
  // direction (the projected width vector is not perpendicular in a perspective view).
  const auto c2 = hal::project(k_, pose_, {px + gx / len * 0.05, py + gy / len * 0.05, 0.0});
  if (!c2) return -1;
  double dx = c2->u - c->u, dy = c2->v - c->v;
  const double dl = std::sqrt(dx * dx + dy * dy);
  if (dl < 1e-9) return -1;
  dx /= dl;
  dy /= dl;
  const double half = std::max(h, 0.5);
  if (looks_like_line(c->u, c->v, -dy, dx, half)) return 1;
  if (h >= params_.thin_half_width_px) return 0;
  for (int d = 1; d <= params_.thin_reach_px; ++d) {
    for (const int sign : {1, -1}) {
      if (looks_like_line(c->u + sign * d * dx, c->v + sign * d * dy, -dy, dx, half)) return 1;
    }
  }
  return 0;
}

LineCheck::Verdict LineCheck::assess(const hal::RobotPoint& a, const hal::RobotPoint& b) const noexcept {
  if (hal::portable_hypot(b.x - a.x, b.y - a.y) < 1e-9) return {};
  const int n = std::max(params_.samples, 1);
  int judged = 0;
  int passed = 0;
  // The painted span: from each end inwards, samples that are judged and fail are cut; one that
  // passes, or one outside the picture (not judged: nothing to say), stops the cut.
  int first = -1;  // first and last sample that does not fail
  int last = -1;
  for (int i = 0; i < n; ++i) {
    const int r = judge(a, b, i, n);
    judged += r >= 0 ? 1 : 0;
    passed += r > 0 ? 1 : 0;
    if (r != 0) {
      if (first < 0) first = i;
      last = i;
    }
  }
  Verdict v;
  v.share = judged < params_.min_judged ? 1.0 : static_cast<double>(passed) / static_cast<double>(judged);
  v.accepted = v.share >= params_.min_share;
  // The cut goes to the middle between the last failing and the first passing sample; nothing but
  // failing samples: nothing to cut back to, the piece is left as it is.
  if (first >= 0) {
    const double dn = static_cast<double>(n);
    v.span = {first == 0 ? 0.0 : static_cast<double>(first) / dn,
              last == n - 1 ? 1.0 : static_cast<double>(last + 1) / dn};
  }
  return v;
}

double LineCheck::share(const hal::RobotPoint& a, const hal::RobotPoint& b) const noexcept { return assess(a, b).share; }

LineCheck::Span LineCheck::painted_span(const hal::RobotPoint& a, const hal::RobotPoint& b) const noexcept {
  return judge_piece(a, b).span;
}

}  // namespace ringlet::vision
