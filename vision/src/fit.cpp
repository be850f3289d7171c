// The fits as small fixed-size linear algebra (Eigen's 2×2 and 3×3 types, on the stack: the
// RANSAC rounds call these on the cycle path, where nothing may allocate).
#include "ringlet/vision/fit.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "ringlet/hal/portable_math.hpp"

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

/// Point i relative to m.
Eigen::Vector2d centred(const IndexedPoints& pts, std::size_t i, const hal::RobotPoint& m) noexcept {
  return {pts[i].x - m.x, pts[i].y - m.y};
}

}  // namespace

std::optional<Line2> fit_line_tls(const IndexedPoints& pts) noexcept {
  if (pts.size() < 2) return std::nullopt;
  const hal::RobotPoint m = mean(pts);
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector2d d = centred(pts, i, m);
    scatter += d * d.transpose();
  }
  if (scatter.trace() < 1e-18) return std::nullopt;
  // The line runs along the scatter matrix's principal axis: the eigenvector of its larger
  // eigenvalue (Eigen sorts them ascending). The iterative solver, not computeDirect's closed
  // form: it stays accurate when the two eigenvalues are close, and its iterations are bounded.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(scatter);
  if (eigen.info() != Eigen::Success) return std::nullopt;
  Eigen::Vector2d axis = eigen.eigenvectors().col(1);
  // An eigenvector's sign is arbitrary; fix it (towards +x, or +y when vertical) so that the
  // same points always give the same direction, and so the same order of points along it.
  if (axis.x() < 0.0 || (axis.x() == 0.0 && axis.y() < 0.0)) axis = -axis;
  return Line2{m, axis.x(), axis.y()};
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
  // Normal equations of  minimise Σ (z + D x + E y + F)², z = x² + y², in centred coordinates:
  // Σ r rᵀ [D E F]ᵀ = −Σ r z  with r = (x, y, 1).
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector2d d = centred(pts, i, m);
    const Eigen::Vector3d r{d.x(), d.y(), 1.0};
    normal += r * r.transpose();
    rhs -= d.squaredNorm() * r;
  }
  const auto n = static_cast<double>(pts.size());
  const double spread = normal(0, 0) + normal(1, 1);
  const double scale = spread * spread * n;
  if (!(std::abs(normal.determinant()) > 1e-12 * scale) || scale <= 0.0) return std::nullopt;
  // Pivoted LDLT rather than Cramer's rule: backward stable, and the matrix is symmetric
  // positive definite once the points are not collinear.
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(normal);
  if (ldlt.info() != Eigen::Success) return std::nullopt;
  const Eigen::Vector3d sol = ldlt.solve(rhs);
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
    const double d = hal::portable_hypot(pts[i].x - c.centre.x, pts[i].y - c.centre.y) - c.radius;
    s += d * d;
  }
  return std::sqrt(s / static_cast<double>(pts.size()));
}

std::optional<Circle2> fit_circle_geometric(const IndexedPoints& pts, const Circle2& start, bool fixed_radius,
                                            int iterations) noexcept {
  if (pts.size() < (fixed_radius ? 2U : 3U) || !(start.radius > 0.0)) return std::nullopt;
  Circle2 c = start;
  for (int it = 0; it < iterations; ++it) {
    // Residual r_i = |p_i − c| − R; ∂r/∂c = −(p − c)/|p − c|, ∂r/∂R = −1.
    // JᵀJ and Jᵀr summed as scalars (six distinct entries; a 3×3 outer product per point was a
    // fifth of the circle stage's time). The same products in the same order: the same sums.
    double xx = 0.0, xy = 0.0, x1 = 0.0, yy = 0.0, y1 = 0.0, n = 0.0, rx = 0.0, ry = 0.0, r1 = 0.0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double ux = pts[i].x - c.centre.x;
      const double uy = pts[i].y - c.centre.y;
      const double d = hal::portable_hypot(ux, uy);
      if (d < 1e-9) continue;  // a point at the centre has no direction
      const double jx = -ux / d, jy = -uy / d;  // and ∂r/∂R = −1
      const double r = d - c.radius;
      xx += jx * jx;
      xy += jx * jy;
      x1 += jx * -1.0;
      yy += jy * jy;
      y1 += jy * -1.0;
      n += -1.0 * -1.0;
      rx += jx * r;
      ry += jy * r;
      r1 += -1.0 * r;
    }
    Eigen::Matrix3d jtj;
    jtj << xx, xy, x1, xy, yy, y1, x1, y1, n;
    const Eigen::Vector3d jtr{rx, ry, r1};
    Eigen::Vector3d step = Eigen::Vector3d::Zero();
    if (fixed_radius) {
      const Eigen::Matrix2d a = jtj.topLeftCorner<2, 2>();
      if (!(std::abs(a.determinant()) > 1e-12 * (a.trace() * a.trace() + 1e-300))) return std::nullopt;
      step.head<2>() = -a.ldlt().solve(jtr.head<2>());
    } else {
      const Eigen::LDLT<Eigen::Matrix3d> ldlt(jtj);
      if (ldlt.info() != Eigen::Success || !(std::abs(jtj.determinant()) > 1e-12 * std::pow(jtj.trace(), 3.0))) {
        return std::nullopt;
      }
      step = -ldlt.solve(jtr);
    }
    if (!step.allFinite()) return std::nullopt;
    c.centre.x += step[0];
    c.centre.y += step[1];
    c.radius += step[2];
    if (!(c.radius > 0.0)) return std::nullopt;
    if (step.norm() < 1e-7) break;
  }
  return c;
}

std::optional<Bend> fit_bend(const Line2& line, const IndexedPoints& pts, double noise_floor_m) noexcept {
  if (pts.size() < 5) return std::nullopt;
  double t_lo = 1e300, t_hi = -1e300;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double t = line.along(pts[i]);
    t_lo = std::min(t_lo, t);
    t_hi = std::max(t_hi, t);
  }
  const double span = t_hi - t_lo;
  if (!(span > 1e-6)) return std::nullopt;
  const double mid = (t_lo + t_hi) / 2.0;
  // Normal equations of d = a + b·u + c·u², u = (t − mid) / half span (scaled for conditioning).
  const double half = span / 2.0;
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double u = (line.along(pts[i]) - mid) / half;
    const Eigen::Vector3d r{1.0, u, u * u};
    normal += r * r.transpose();
    rhs += line.signed_distance(pts[i]) * r;
  }
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(normal);
  if (ldlt.info() != Eigen::Success || !(std::abs(normal.determinant()) > 1e-12 * std::pow(normal.trace(), 3.0))) {
    return std::nullopt;
  }
  const Eigen::Vector3d sol = ldlt.solve(rhs);
  if (!sol.allFinite()) return std::nullopt;
  double ssr = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double u = (line.along(pts[i]) - mid) / half;
    const double e = line.signed_distance(pts[i]) - (sol[0] + sol[1] * u + sol[2] * u * u);
    ssr += e * e;
  }
  const auto n = static_cast<double>(pts.size());
  const double noise = std::max(std::sqrt(ssr / (n - 3.0)), noise_floor_m);
  // Var(ĉ) = σ² (NᵀN)⁻¹₂₂: the last diagonal entry of the inverse, via one solve.
  const Eigen::Vector3d e2 = ldlt.solve(Eigen::Vector3d{0.0, 0.0, 1.0});
  const double var_unit = std::max(e2[2], 0.0);
  Bend b;
  b.c = sol[2] / (half * half);
  b.sigma_c = noise * std::sqrt(var_unit) / (half * half);
  b.b = sol[1] / half;
  b.a = sol[0];
  b.t_mid = mid;
  b.span = span;
  b.n = static_cast<int>(pts.size());
  return b;
}

}  // namespace ringlet::vision
