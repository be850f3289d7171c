// The fits as small fixed-size linear algebra (Eigen's 2×2 and 3×3 types, on the stack: the
// RANSAC rounds call these on the cycle path, where nothing may allocate).
#include "ringlet/vision/fit.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
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
    const double d = std::hypot(pts[i].x - c.centre.x, pts[i].y - c.centre.y) - c.radius;
    s += d * d;
  }
  return std::sqrt(s / static_cast<double>(pts.size()));
}

}  // namespace ringlet::vision
