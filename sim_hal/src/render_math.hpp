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
