// Ray and disc queries against circles, polygon edges and the four walls of the bounds. They run
// every cycle (the laser casts one ray per beam), so they only read the World, never allocate.
#include "ringlet/sim_hal/collision.hpp"

#include <cmath>

#include "vec2_math.hpp"

namespace ringlet::sim_hal {
namespace {

using detail::operator-;
using detail::cross;
using detail::dot;
using detail::length_squared;
using detail::segment_distance_squared;

constexpr double kNoHit = std::numeric_limits<double>::infinity();

/// First t >= 0 where origin + t*dir (|dir| = 1) meets the circle's rim, or +inf.
double ray_circle(Vec2 origin, Vec2 dir, const Circle& circle) noexcept {
  const Vec2 offset = origin - circle.centre;
  const double b = dot(offset, dir);
  const double c = length_squared(offset) - circle.radius * circle.radius;
  const double discriminant = b * b - c;
  if (discriminant < 0.0) return kNoHit;
  const double root = std::sqrt(discriminant);
  if (const double near = -b - root; near >= 0.0) return near;
  // Origin inside the circle: the rim is met on the way out.
  if (const double far = -b + root; far >= 0.0) return far;
  return kNoHit;
}

/// First t >= 0 where origin + t*dir meets the closed segment [a, b], or +inf. A ray running
/// parallel to the segment is not counted: it would meet a neighbouring edge at the same point.
double ray_segment(Vec2 origin, Vec2 dir, Vec2 a, Vec2 b) noexcept {
  const Vec2 edge = b - a;
  const double denominator = cross(dir, edge);
  if (denominator == 0.0) return kNoHit;
  const Vec2 to_a = a - origin;
  const double t = cross(to_a, edge) / denominator;
  const double u = cross(to_a, dir) / denominator;
  return (t >= 0.0 && u >= 0.0 && u <= 1.0) ? t : kNoHit;
}

/// Distance to the walls from inside the bounds: the nearer of the x wall and the y wall ahead.
double ray_walls(const World& world, Vec2 origin, Vec2 dir) noexcept {
  double best = kNoHit;
  if (dir.x > 0.0) best = std::fmin(best, (world.max.x - origin.x) / dir.x);
  if (dir.x < 0.0) best = std::fmin(best, (world.min.x - origin.x) / dir.x);
  if (dir.y > 0.0) best = std::fmin(best, (world.max.y - origin.y) / dir.y);
  if (dir.y < 0.0) best = std::fmin(best, (world.min.y - origin.y) / dir.y);
  return best < 0.0 ? 0.0 : best;  // an origin outside the bounds is already at the wall
}

/// Even-odd rule: a horizontal ray from p crosses the outline an odd number of times when inside.
bool inside_polygon(Vec2 p, const Polygon& polygon) noexcept {
  const auto& v = polygon.vertices;
  bool inside = false;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    if ((v[i].y > p.y) != (v[j].y > p.y)) {
      const double x_cross = v[j].x + (p.y - v[j].y) / (v[i].y - v[j].y) * (v[i].x - v[j].x);
      if (p.x < x_cross) inside = !inside;
    }
  }
  return inside;
}

/// The indices 0 .. n − 1 as a range (std::views::iota trips clang 14 with libstdc++ 12).
struct FirstN {
  std::size_t n;
  struct Iterator {
    std::size_t i;
    std::size_t operator*() const noexcept { return i; }
    Iterator& operator++() noexcept {
      ++i;
      return *this;
    }
    bool operator!=(const Iterator& o) const noexcept { return i != o.i; }
  };
  [[nodiscard]] Iterator begin() const noexcept { return {0}; }
  [[nodiscard]] Iterator end() const noexcept { return {n}; }
};

/// The first hit among the given circles and polygons (and the walls), or +inf beyond max_range.
template <class CircleIndices, class PolygonIndices>
double cast_among(const World& world, Vec2 origin, double bearing, double max_range, const CircleIndices& circles,
                  const PolygonIndices& polygons) noexcept {
  // Bearing convention of geometry.hpp: 0 looks along +y, pi/2 along +x.
  const Vec2 dir{std::sin(bearing), std::cos(bearing)};
  double best = ray_walls(world, origin, dir);
  for (const auto c : circles) best = std::fmin(best, ray_circle(origin, dir, world.circles[c]));
  for (const auto p : polygons) {
    const auto& v = world.polygons[p].vertices;
    for (std::size_t i = 0; i < v.size(); ++i) best = std::fmin(best, ray_segment(origin, dir, v[i], v[(i + 1) % v.size()]));
  }
  return best <= max_range ? best : kNoHit;
}

}  // namespace

double cast_ray(const World& world, Vec2 origin, double bearing, double max_range) noexcept {
  return cast_among(world, origin, bearing, max_range, FirstN{world.circles.size()}, FirstN{world.polygons.size()});
}

void RayCandidates::reserve(const World& world) {
  circles_.reserve(world.circles.size());
  polygons_.reserve(world.polygons.size());
}

void RayCandidates::select(const World& world, Vec2 origin, double max_range) noexcept {
  circles_.clear();
  polygons_.clear();
  for (std::size_t i = 0; i < world.circles.size() && circles_.size() < circles_.capacity(); ++i) {
    const Circle& c = world.circles[i];
    const double reach = max_range + c.radius;
    if (length_squared(origin - c.centre) <= reach * reach) circles_.push_back(static_cast<std::uint32_t>(i));
  }
  const double range_squared = max_range * max_range;
  for (std::size_t i = 0; i < world.polygons.size() && polygons_.size() < polygons_.capacity(); ++i) {
    const auto& v = world.polygons[i].vertices;
    bool near = false;
    for (std::size_t k = 0; k < v.size() && !near; ++k) {
      near = segment_distance_squared(origin, v[k], v[(k + 1) % v.size()]) <= range_squared;
    }
    if (near) polygons_.push_back(static_cast<std::uint32_t>(i));
  }
}

double RayCandidates::cast(const World& world, Vec2 origin, double bearing, double max_range) const noexcept {
  // As cast_ray, over the candidates only: a hit beyond max_range is no hit either way.
  return cast_among(world, origin, bearing, max_range, circles_, polygons_);
}

bool disc_collides(const World& world, Vec2 centre, double radius) noexcept {
  if (centre.x - radius < world.min.x || centre.x + radius > world.max.x || centre.y - radius < world.min.y ||
      centre.y + radius > world.max.y) {
    return true;
  }
  for (const Circle& circle : world.circles) {
    const double reach = circle.radius + radius;
    if (length_squared(centre - circle.centre) < reach * reach) return true;
  }
  const double radius_squared = radius * radius;
  for (const Polygon& polygon : world.polygons) {
    const auto& v = polygon.vertices;
    if (v.empty()) continue;
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (segment_distance_squared(centre, v[i], v[(i + 1) % v.size()]) < radius_squared) return true;
    }
    // Entirely inside a large obstacle: no edge is near, but it is still a collision.
    if (inside_polygon(centre, polygon)) return true;
  }
  return false;
}

}  // namespace ringlet::sim_hal
