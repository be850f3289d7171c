#pragma once
// The few vector operations the geometry code needs, kept inline so the cycle-time queries stay
// allocation-free and cheap.
#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal::detail {

constexpr Vec2 operator+(Vec2 a, Vec2 b) noexcept { return {a.x + b.x, a.y + b.y}; }
constexpr Vec2 operator-(Vec2 a, Vec2 b) noexcept { return {a.x - b.x, a.y - b.y}; }
constexpr Vec2 operator*(double s, Vec2 a) noexcept { return {s * a.x, s * a.y}; }
constexpr double dot(Vec2 a, Vec2 b) noexcept { return a.x * b.x + a.y * b.y; }
/// z component of the 3-D cross product: > 0 when b lies counter-clockwise of a.
constexpr double cross(Vec2 a, Vec2 b) noexcept { return a.x * b.y - a.y * b.x; }
constexpr double length_squared(Vec2 a) noexcept { return dot(a, a); }

/// Squared distance from p to the closed segment [a, b].
constexpr double segment_distance_squared(Vec2 p, Vec2 a, Vec2 b) noexcept {
  const Vec2 ab = b - a;
  const double len2 = length_squared(ab);
  if (len2 == 0.0) return length_squared(p - a);
  double t = dot(p - a, ab) / len2;
  t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
  return length_squared(p - (a + t * ab));
}

}  // namespace ringlet::sim_hal::detail
