#pragma once
// Small 3-D helpers for the camera renderer and its ground truth: vector arithmetic, the first
// hit of a ray with an obstacle cylinder or the ball, and integer-hash noise. Everything here is
// plain arithmetic on doubles and integers, so it gives the same bits for the same inputs on
// every target (the build uses -ffp-contract=off).
#include <cmath>
#include <cstdint>
#include <limits>

#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal::detail {

using hal::Vec3;

constexpr double kNoHit3 = std::numeric_limits<double>::infinity();

constexpr Vec3 add(const Vec3& a, const Vec3& b) noexcept { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr Vec3 sub(const Vec3& a, const Vec3& b) noexcept { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr Vec3 scale(double s, const Vec3& a) noexcept { return {s * a.x, s * a.y, s * a.z}; }
constexpr double dot(const Vec3& a, const Vec3& b) noexcept { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// A robot-frame vector in the world frame for a robot at heading theta (geometry.hpp: ahead is
/// (sin θ, cos θ), left is (−cos θ, sin θ)).
inline Vec3 robot_to_world_direction(double sin_theta, double cos_theta, const Vec3& r) noexcept {
  return {r.x * sin_theta - r.y * cos_theta, r.x * cos_theta + r.y * sin_theta, r.z};
}

/// Smallest t > 0 with o + t·d inside the closed vertical cylinder (side or top cap), or +inf.
/// d need not be normalised; t is in units of d.
inline double ray_cylinder(const Vec3& o, const Vec3& d, const Circle& c) noexcept {
  const double ox = o.x - c.centre.x;
  const double oy = o.y - c.centre.y;
  const double a = d.x * d.x + d.y * d.y;
  const double r2 = c.radius * c.radius;
  const double b = ox * d.x + oy * d.y;
  const double cc = ox * ox + oy * oy - r2;
  if (a > 0.0) {
    const double disc = b * b - a * cc;
    if (disc < 0.0) return kNoHit3;
    const double t = (-b - std::sqrt(disc)) / a;  // entering the infinite cylinder
    if (t > 0.0) {
      const double z = o.z + t * d.z;
      if (z >= 0.0 && z <= c.height) return t;
      // Passing over the top: it may still come down through the cap.
      if (z > c.height && d.z < 0.0) {
        const double tc = (c.height - o.z) / d.z;
        const double x = ox + tc * d.x;
        const double y = oy + tc * d.y;
        if (tc > 0.0 && x * x + y * y <= r2) return tc;
      }
      return kNoHit3;
    }
  }
  // Camera above the cylinder's footprint (or straight down): only the cap can be hit.
  if (cc <= 0.0 && o.z > c.height && d.z < 0.0) return (c.height - o.z) / d.z;
  return kNoHit3;
}

/// Smallest t > 0 where o + t·d meets the sphere of `radius` at `centre`, or +inf.
inline double ray_sphere(const Vec3& o, const Vec3& d, const Vec3& centre, double radius) noexcept {
  const Vec3 oc = sub(o, centre);
  const double a = dot(d, d);
  const double b = dot(oc, d);
  const double c = dot(oc, oc) - radius * radius;
  const double disc = b * b - a * c;
  if (disc < 0.0) return kNoHit3;
  const double t = (-b - std::sqrt(disc)) / a;
  return t > 0.0 ? t : kNoHit3;
}

/// Smallest t > 0 where o + t·d meets the axis-aligned ellipsoid of semi-axes 1 / inv_radii at
/// `centre`, or +inf. `normal` gets the outward normal there (not normalised).
inline double ray_ellipsoid(const Vec3& o, const Vec3& d, const Vec3& centre, const Vec3& inv_radii,
                            Vec3& normal) noexcept {
  const Vec3 oc{(o.x - centre.x) * inv_radii.x, (o.y - centre.y) * inv_radii.y, (o.z - centre.z) * inv_radii.z};
  const Vec3 ds{d.x * inv_radii.x, d.y * inv_radii.y, d.z * inv_radii.z};
  const double a = dot(ds, ds);
  const double b = dot(oc, ds);
  const double c = dot(oc, oc) - 1.0;
  const double disc = b * b - a * c;
  if (disc < 0.0) return kNoHit3;
  const double t = (-b - std::sqrt(disc)) / a;
  if (!(t > 0.0)) return kNoHit3;
  const Vec3 q = add(oc, scale(t, ds));  // on the unit sphere
  normal = {q.x * inv_radii.x, q.y * inv_radii.y, q.z * inv_radii.z};
  return t;
}

/// Smallest t > 0 where o + t·d enters the axis-aligned box [lo, hi], or +inf; `axis` gets the
/// entered face's axis (0, 1, 2) and `side` its sign (-1 low face, +1 high face).
inline double ray_box(const Vec3& o, const Vec3& d, const Vec3& lo, const Vec3& hi, int& axis, double& side) noexcept {
  double t_in = -kNoHit3;
  double t_out = kNoHit3;
  const double os[3] = {o.x, o.y, o.z};
  const double ds[3] = {d.x, d.y, d.z};
  const double los[3] = {lo.x, lo.y, lo.z};
  const double his[3] = {hi.x, hi.y, hi.z};
  for (int i = 0; i < 3; ++i) {
    if (ds[i] == 0.0) {
      if (os[i] < los[i] || os[i] > his[i]) return kNoHit3;
      continue;
    }
    const double inv = 1.0 / ds[i];
    double t0 = (los[i] - os[i]) * inv;
    double t1 = (his[i] - os[i]) * inv;
    double s = -1.0;
    if (t0 > t1) {
      const double tmp = t0;
      t0 = t1;
      t1 = tmp;
      s = 1.0;
    }
    if (t0 > t_in) {
      t_in = t0;
      axis = i;
      side = s;
    }
    if (t1 < t_out) t_out = t1;
  }
  if (t_in > t_out || !(t_in > 0.0)) return kNoHit3;
  return t_in;
}

/// floor() for values well inside the int range, without a libm call in the pixel loop.
inline int fast_floor(double v) noexcept {
  const int i = static_cast<int>(v);
  return v < static_cast<double>(i) ? i - 1 : i;
}

/// A well-mixed 32-bit hash of two integer coordinates and a seed (lowbias32-style finaliser).
constexpr std::uint32_t hash2(int x, int y, std::uint32_t seed) noexcept {
  std::uint32_t h = seed ^ (static_cast<std::uint32_t>(x) * 0x8da6b343U) ^ (static_cast<std::uint32_t>(y) * 0xd8163841U);
  h ^= h >> 16;
  h *= 0x7feb352dU;
  h ^= h >> 15;
  h *= 0x846ca68bU;
  h ^= h >> 16;
  return h;
}

/// A hash as a double in [0, 1).
constexpr double unit(std::uint32_t h) noexcept { return static_cast<double>(h >> 8) * (1.0 / 16777216.0); }

/// Value noise in [0, 1): the hashes of the four lattice points around (x, y), blended
/// bilinearly, so it varies smoothly over one lattice cell.
inline double value_noise(double x, double y, std::uint32_t seed) noexcept {
  const int ix = fast_floor(x);
  const int iy = fast_floor(y);
  const double fx = x - static_cast<double>(ix);
  const double fy = y - static_cast<double>(iy);
  const double a = unit(hash2(ix, iy, seed));
  const double b = unit(hash2(ix + 1, iy, seed));
  const double c = unit(hash2(ix, iy + 1, seed));
  const double d = unit(hash2(ix + 1, iy + 1, seed));
  const double top = a + (b - a) * fx;
  const double bottom = c + (d - c) * fx;
  return top + (bottom - top) * fy;
}

}  // namespace ringlet::sim_hal::detail
