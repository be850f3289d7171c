#include "ringlet/behaviour/reactive/arcs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ringlet/hal/portable_math.hpp"

namespace ringlet::behaviour::reactive {

std::string ArcSet::validate() const {
  if (count < 1 || count > kMaxArcs) return "arcs must be 1 to " + std::to_string(kMaxArcs);
  if (!(max_curvature > 0.0) || !std::isfinite(max_curvature)) return "max_curvature must be a positive curvature in 1/m";
  return {};
}

ObstaclePoints obstacles_from_scan(const hal::LaserScan& scan) noexcept {
  ObstaclePoints o;
  const std::size_t beams = std::min<std::size_t>(scan.beam_count, hal::LaserScan::kMaxBeams);
  for (std::size_t i = 0; i < beams; ++i) {
    if (!scan.valid[i] || !std::isfinite(scan.range[i])) continue;
    // Beam angles have theta's sense (positive to the right); the robot frame's y is to the left.
    const double a = scan.beam_angle(i), r = static_cast<double>(scan.range[i]);
    o.point[o.count++] = {r * std::cos(a), -r * std::sin(a)};
  }
  return o;
}

namespace {

/// How close the arc comes to `p` within `limit` of travel (the start included).
double closest_approach(double kappa, const hal::RobotPoint& p, double limit) noexcept {
  const double here = hal::portable_hypot(p.x, p.y);
  if (std::abs(kappa) < 1e-6) return p.x > 0.0 ? hal::portable_hypot(std::max(0.0, p.x - limit), p.y) : here;
  const double R = 1.0 / std::abs(kappa);
  const double qx = p.x, qy = (kappa > 0.0 ? p.y : -p.y) + R;
  double phi = std::atan2(qx, qy);
  if (phi < 0.0) phi += 2.0 * std::numbers::pi;
  const double rho = hal::portable_hypot(qx, qy);
  if (R * phi <= limit) return std::abs(rho - R);  // the arc passes the point nearest to p
  // Else the nearest of the reachable arc is its end (the distance to p falls, then rises).
  const double a = limit / R;
  const double ex = R * std::sin(a), ey = (kappa > 0.0 ? -1.0 : 1.0) * R * (1.0 - std::cos(a));
  return std::min(here, hal::portable_hypot(p.x - ex, p.y - ey));
}

}  // namespace

double distance_to_contact(double kappa, const hal::RobotPoint& p, double radius, double limit) noexcept {
  const double r2 = radius * radius;
  if (p.x * p.x + p.y * p.y <= r2) {
    // Already inside the point's configuration space (a late sighting, a wall alongside): only an
    // arc that brings the robot closer still counts as touching it now; one that leads away is
    // how to get out.
    return closest_approach(kappa, p, limit) < std::sqrt(p.x * p.x + p.y * p.y) - 1e-6 ? 0.0 : limit;
  }
  if (std::abs(kappa) < 1e-6) {  // straight ahead: the disc's near edge on the x axis
    if (std::abs(p.y) >= radius) return limit;
    const double d = p.x - std::sqrt(r2 - p.y * p.y);
    return d >= 0.0 ? std::min(d, limit) : limit;  // behind the robot
  }
  // Mirror a left turn into a right one; then the centre is at (0, −R) and the robot moves
  // clockwise around it from angle 0 (straight "up" from the centre).
  const double R = 1.0 / std::abs(kappa);
  const double qx = p.x, qy = (kappa > 0.0 ? p.y : -p.y) + R;
  const double rho = std::sqrt(qx * qx + qy * qy);
  if (std::abs(rho - R) >= radius) return limit;  // the circle passes the disc by
  double phi = std::atan2(qx, qy);  // the point's clockwise angle from the start
  if (phi < 0.0) phi += 2.0 * std::numbers::pi;
  const double c = std::clamp((R * R + rho * rho - r2) / (2.0 * R * rho), -1.0, 1.0);
  const double d = R * (phi - std::acos(c));  // the first angle at which the circle meets the disc
  return d >= 0.0 ? std::min(d, limit) : 0.0;
}

void clearances(const ArcSet& arcs, const ObstaclePoints& obstacles, double radius, double limit, PerArc& out) noexcept {
  const double reach2 = (limit + radius) * (limit + radius);
  for (int i = 0; i < arcs.count; ++i) out[static_cast<std::size_t>(i)] = limit;
  for (std::size_t k = 0; k < obstacles.count; ++k) {
    const hal::RobotPoint& p = obstacles.point[k];
    if (p.x * p.x + p.y * p.y > reach2) continue;  // no arc reaches it within the limit
    for (int i = 0; i < arcs.count; ++i) {
      double& d = out[static_cast<std::size_t>(i)];
      d = std::min(d, distance_to_contact(arcs.curvature(i), p, radius, d));
    }
  }
}

}  // namespace ringlet::behaviour::reactive
