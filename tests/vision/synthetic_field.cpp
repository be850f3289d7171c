#include "synthetic_field.hpp"

#include <algorithm>
#include <cmath>

#include "ringlet/vision/colour.hpp"

namespace ringlet::vision::testing {
namespace {

double segment_distance(const hal::RobotPoint& p, const GroundSegment& s) {
  const double vx = s.b.x - s.a.x, vy = s.b.y - s.a.y;
  const double len2 = vx * vx + vy * vy;
  const double t = len2 > 0.0 ? std::clamp(((p.x - s.a.x) * vx + (p.y - s.a.y) * vy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - (s.a.x + t * vx), p.y - (s.a.y + t * vy));
}

std::uint8_t jitter(std::uint8_t c, int noise, std::uint32_t h) {
  if (noise <= 0) return c;
  const int d = static_cast<int>(h % static_cast<std::uint32_t>(2 * noise + 1)) - noise;
  return static_cast<std::uint8_t>(std::clamp(static_cast<int>(c) + d, 0, 255));
}

std::uint32_t hash(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

Bgr shade(const Scene& scene, const Camera& cam, const hal::CameraPose& pose, double u, double v) {
  const hal::Vec3 ray = hal::pixel_ray(cam.k, pose, {u, v});
  if (scene.ball) {
    // Ray–sphere: |o + t d − c|² = R².
    const hal::Vec3 o = pose.position;
    const hal::Vec3 c{scene.ball->x, scene.ball->y, scene.ball_radius};
    const hal::Vec3 oc{o.x - c.x, o.y - c.y, o.z - c.z};
    const double a = ray.x * ray.x + ray.y * ray.y + ray.z * ray.z;
    const double b = 2.0 * (oc.x * ray.x + oc.y * ray.y + oc.z * ray.z);
    const double cc = oc.x * oc.x + oc.y * oc.y + oc.z * oc.z - scene.ball_radius * scene.ball_radius;
    const double disc = b * b - 4.0 * a * cc;
    if (disc >= 0.0 && b < 0.0) {
      if (!scene.ball_black_white) return kOrange;
      // The surface normal where the ray enters; black near the 12 icosahedron vertices (the
      // pentagons of a truncated icosahedron, ~21° across).
      const double t = (-b - std::sqrt(disc)) / (2.0 * a);
      const hal::Vec3 n{(oc.x + t * ray.x) / scene.ball_radius, (oc.y + t * ray.y) / scene.ball_radius,
                        (oc.z + t * ray.z) / scene.ball_radius};
      constexpr double phi = 1.618033988749895;
      const double norm = std::sqrt(1.0 + phi * phi);
      const double vs[12][3] = {{0, 1, phi}, {0, -1, phi}, {0, 1, -phi}, {0, -1, -phi}, {1, phi, 0}, {-1, phi, 0},
                                {1, -phi, 0}, {-1, -phi, 0}, {phi, 0, 1}, {-phi, 0, 1}, {phi, 0, -1}, {-phi, 0, -1}};
      for (const auto& vertex : vs) {
        if ((n.x * vertex[0] + n.y * vertex[1] + n.z * vertex[2]) / norm > 0.93) return kBallBlack;
      }
      return kWhite;
    }
  }
  if (!(ray.z < -1e-12)) return kWall;
  const double t = -pose.position.z / ray.z;
  const hal::RobotPoint g{pose.position.x + t * ray.x, pose.position.y + t * ray.y};
  for (const GroundBox& box : scene.blobs) {
    if (g.x >= box.min.x && g.x <= box.max.x && g.y >= box.min.y && g.y <= box.max.y) return kWhite;
  }
  for (const GroundSegment& s : scene.lines) {
    if (segment_distance(g, s) <= s.width / 2.0) return kWhite;
  }
  for (const GroundRing& r : scene.rings) {
    if (std::abs(std::hypot(g.x - r.centre.x, g.y - r.centre.y) - r.radius) <= r.width / 2.0) return kWhite;
  }
  return kGreen;
}

}  // namespace

Frame render(const Scene& scene, const Camera& cam, hal::PixelFormat format, std::uint64_t sequence) {
  const int w = cam.k.width, h = cam.k.height;
  const hal::CameraPose pose = cam.pose();
  std::vector<Bgr> bgr(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      Bgr c = shade(scene, cam, pose, x + 0.5, y + 0.5);
      const auto seed = static_cast<std::uint32_t>(y * w + x) * 3U;
      c = {jitter(c.b, scene.noise, hash(seed)), jitter(c.g, scene.noise, hash(seed + 1)),
           jitter(c.r, scene.noise, hash(seed + 2))};
      bgr[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)] = c;
    }
  }
  Frame f;
  f.view.sequence = sequence;
  f.view.format = format;
  f.view.width = w;
  f.view.height = h;
  if (format == hal::PixelFormat::kBgr8) {
    f.view.stride = 3 * w;
    f.bytes.resize(static_cast<std::size_t>(f.view.stride) * static_cast<std::size_t>(h));
    for (std::size_t i = 0; i < bgr.size(); ++i) {
      f.bytes[3 * i] = bgr[i].b;
      f.bytes[3 * i + 1] = bgr[i].g;
      f.bytes[3 * i + 2] = bgr[i].r;
    }
  } else {
    // YUYV: each pair of pixels shares the mean of their U and V.
    f.view.format = hal::PixelFormat::kYuyv;
    f.view.stride = 2 * w;
    f.bytes.resize(static_cast<std::size_t>(f.view.stride) * static_cast<std::size_t>(h));
    for (std::size_t i = 0; i + 1 < bgr.size(); i += 2) {
      const Yuv p0 = bgr_to_yuv(bgr[i].b, bgr[i].g, bgr[i].r);
      const Yuv p1 = bgr_to_yuv(bgr[i + 1].b, bgr[i + 1].g, bgr[i + 1].r);
      f.bytes[2 * i] = p0.y;
      f.bytes[2 * i + 1] = static_cast<std::uint8_t>((p0.u + p1.u + 1) / 2);
      f.bytes[2 * i + 2] = p1.y;
      f.bytes[2 * i + 3] = static_cast<std::uint8_t>((p0.v + p1.v + 1) / 2);
    }
  }
  f.view.data = f.bytes.data();
  return f;
}

Scene field_scene() {
  Scene s;
  s.lines = {{{3.0, -3.0}, {3.0, 3.0}},     // halfway line, across the view
             {{0.8, 1.2}, {6.0, 1.2}}};     // a touch line running away on the left
  s.rings = {{{3.0, 0.0}, 0.75}};
  s.ball = hal::RobotPoint{1.4, -0.4};
  s.noise = 6;
  return s;
}

Scene classifier_scene() {
  Scene s = field_scene();
  s.ball_black_white = true;
  s.blobs.push_back({{1.0, 0.5}, {1.3, 0.7}});
  return s;
}

}  // namespace ringlet::vision::testing
