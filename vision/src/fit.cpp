#include "ringlet/vision/fit.hpp"

#include <cmath>

namespace ringlet::vision {
namespace {

hal::RobotPoint mean(const IndexedPoints& pts) noexcept {
  double sx = 0.0, sy = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    sx += pts[i].x;
    sy += pts[i].y;
  }
  const auto n = static_cast<double>(pts.size());
  return {sx / n, sy / n};
}

}  // namespace

std::optional<Line2> fit_line_tls(const IndexedPoints& pts) noexcept {
  if (pts.size() < 2) return std::nullopt;
  const hal::RobotPoint m = mean(pts);
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double x = pts[i].x - m.x;
    const double y = pts[i].y - m.y;
    sxx += x * x;
    sxy += x * y;
    syy += y * y;
  }
  if (sxx + syy < 1e-18) return std::nullopt;
  // Principal axis of the 2×2 scatter matrix: angle θ with tan 2θ = 2 sxy / (sxx − syy).
  const double theta = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  return Line2{m, std::cos(theta), std::sin(theta)};
}

double line_rms(const Line2& line, const IndexedPoints& pts) noexcept {
  if (pts.size() == 0) return 0.0;
  double s = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double d = line.signed_distance(pts[i]);
    s += d * d;
  }
  return std::sqrt(s / static_cast<double>(pts.size()));
}

std::optional<Circle2> fit_circle(const IndexedPoints& pts) noexcept {
  if (pts.size() < 3) return std::nullopt;
  const hal::RobotPoint m = mean(pts);
  // Normal equations of  minimise Σ (z + D x + E y + F)², z = x² + y², in centred coordinates.
  double sxx = 0, sxy = 0, syy = 0, sx = 0, sy = 0, sxz = 0, syz = 0, sz = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double x = pts[i].x - m.x;
    const double y = pts[i].y - m.y;
    const double z = x * x + y * y;
    sxx += x * x;
    sxy += x * y;
    syy += y * y;
    sx += x;
    sy += y;
    sxz += x * z;
    syz += y * z;
    sz += z;
  }
  const auto n = static_cast<double>(pts.size());
  // [sxx sxy sx; sxy syy sy; sx sy n] [D E F]ᵀ = −[sxz syz sz]ᵀ, solved by Cramer's rule.
  const double a[3][3] = {{sxx, sxy, sx}, {sxy, syy, sy}, {sx, sy, n}};
  const double b[3] = {-sxz, -syz, -sz};
  const auto det3 = [](const double mtx[3][3]) {
    return mtx[0][0] * (mtx[1][1] * mtx[2][2] - mtx[1][2] * mtx[2][1]) -
           mtx[0][1] * (mtx[1][0] * mtx[2][2] - mtx[1][2] * mtx[2][0]) +
           mtx[0][2] * (mtx[1][0] * mtx[2][1] - mtx[1][1] * mtx[2][0]);
  };
  const double det = det3(a);
  const double scale = (sxx + syy) * (sxx + syy) * n;
  if (!(std::abs(det) > 1e-12 * scale) || scale <= 0.0) return std::nullopt;
  double sol[3];
  for (int c = 0; c < 3; ++c) {
    double m3[3][3];
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) m3[r][k] = k == c ? b[r] : a[r][k];
    sol[c] = det3(m3) / det;
  }
  const double cx = -sol[0] / 2.0;
  const double cy = -sol[1] / 2.0;
  const double r2 = cx * cx + cy * cy - sol[2];
  if (!(r2 > 0.0)) return std::nullopt;
  return Circle2{{cx + m.x, cy + m.y}, std::sqrt(r2)};
}

double circle_rms(const Circle2& c, const IndexedPoints& pts) noexcept {
  if (pts.size() == 0) return 0.0;
  double s = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double d = std::hypot(pts[i].x - c.centre.x, pts[i].y - c.centre.y) - c.radius;
    s += d * d;
  }
  return std::sqrt(s / static_cast<double>(pts.size()));
}

}  // namespace ringlet::vision
