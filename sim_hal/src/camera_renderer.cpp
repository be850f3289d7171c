// The per-pixel part of the simulated camera. Speed comes from three things: the viewing ray is
// linear in u, so a row needs one multiply-add per component per pixel and no trig; obstacles are
// only tested inside their projected bounding boxes; markings are looked up in a coarse grid of
// the ground instead of being tested one by one.
#include "ringlet/sim_hal/camera_renderer.hpp"

#include <algorithm>
#include <cmath>

#include "render_math.hpp"
#include "vec2_math.hpp"

namespace ringlet::sim_hal {
namespace {

using detail::add;
using detail::dot;
using detail::fast_floor;
using detail::hash2;
using detail::scale;
using detail::sub;
using detail::unit;
using hal::Vec3;

constexpr std::uint32_t kRingBit = 0x8000'0000U;
constexpr int kGround = -1;
constexpr int kNothing = -2;

struct Colour {
  double b = 0.0, g = 0.0, r = 0.0;
};

constexpr Colour kCarpet{40.0, 140.0, 55.0};
constexpr Colour kPaint{235.0, 238.0, 238.0};
constexpr Colour kFloor{112.0, 118.0, 124.0};
constexpr Colour kBackground{95.0, 105.0, 122.0};
constexpr Colour kRobotBody{212.0, 214.0, 218.0};
constexpr Colour kRobotJersey{175.0, 75.0, 30.0};
constexpr Colour kPost{240.0, 240.0, 240.0};
constexpr Colour kObstacle{70.0, 70.0, 76.0};
constexpr Colour kBall{20.0, 115.0, 245.0};

/// Where the jersey band sits on a robot, as a fraction of its height.
constexpr double kJerseyLow = 0.5;
constexpr double kJerseyHigh = 0.62;

std::uint8_t to_byte(double v) noexcept {
  return static_cast<std::uint8_t>(v <= 0.0 ? 0 : (v >= 255.0 ? 255 : static_cast<int>(v + 0.5)));
}

void put(std::uint8_t* out, const Colour& c, double light) noexcept {
  out[0] = to_byte(c.b * light);
  out[1] = to_byte(c.g * light);
  out[2] = to_byte(c.r * light);
}

/// Brightness of the sun stripes at ground point (x, y): 1 ± strength, with edges softened over a
/// twentieth of the period so they are not aliased staircases.
double sun_factor(const Lighting& l, double cos_a, double sin_a, double x, double y) noexcept {
  if (l.sun_strength <= 0.0) return 1.0;
  // Distance across the stripes (perpendicular to their heading), in periods.
  const double s = (x * cos_a - y * sin_a - l.sun_phase) / l.sun_period;
  const double f = s - static_cast<double>(fast_floor(s));
  // Signed distance (in periods) to the nearest edge of the bright half [0, 0.5): > 0 inside.
  const double inside = f < 0.5 ? std::min(f, 0.5 - f) : -std::min(f - 0.5, 1.0 - f);
  const double edge = 0.05;
  const double bright = std::clamp(0.5 + inside / edge, 0.0, 1.0);
  return 1.0 + l.sun_strength * (2.0 * bright - 1.0);
}

}  // namespace

CameraRenderer::CameraRenderer(World world, const CameraSpec& spec, std::uint64_t seed)
    : world_(std::move(world)),
      spec_(spec),
      seed_(static_cast<std::uint32_t>(seed ^ (seed >> 32))),
      bgr_(static_cast<std::size_t>(spec.intrinsics.width) * static_cast<std::size_t>(spec.intrinsics.height) * 3U),
      labels_(static_cast<std::size_t>(spec.intrinsics.width) * static_cast<std::size_t>(spec.intrinsics.height)),
      boxes_(world_.circles.size() + 1),
      row_active_(world_.circles.size() + 1) {
  build_grid();
  truth_.lines.reserve(world_.markings.size() * (world_.circles.size() + 3) + 16);
  truth_.rings.resize(world_.rings.size());
}

void CameraRenderer::build_grid() {
  Grid& g = grid_;
  g.x0 = world_.min.x;
  g.y0 = world_.min.y;
  g.nx = std::max(1, static_cast<int>(std::ceil((world_.max.x - world_.min.x) / g.cell)));
  g.ny = std::max(1, static_cast<int>(std::ceil((world_.max.y - world_.min.y) / g.cell)));
  const double half_diagonal = g.cell * std::sqrt(0.5);
  std::vector<std::vector<std::uint32_t>> cells(static_cast<std::size_t>(g.nx) * static_cast<std::size_t>(g.ny));
  for (int iy = 0; iy < g.ny; ++iy) {
    for (int ix = 0; ix < g.nx; ++ix) {
      const Vec2 centre{g.x0 + (ix + 0.5) * g.cell, g.y0 + (iy + 0.5) * g.cell};
      auto& list = cells[static_cast<std::size_t>(iy) * static_cast<std::size_t>(g.nx) + static_cast<std::size_t>(ix)];
      for (std::size_t m = 0; m < world_.markings.size(); ++m) {
        const Marking& mk = world_.markings[m];
        const double reach = half_diagonal + mk.width / 2.0;
        if (detail::segment_distance_squared(centre, mk.a, mk.b) <= reach * reach) {
          list.push_back(static_cast<std::uint32_t>(m));
        }
      }
      for (std::size_t r = 0; r < world_.rings.size(); ++r) {
        const Ring& ring = world_.rings[r];
        const double d = std::hypot(centre.x - ring.centre.x, centre.y - ring.centre.y);
        if (std::fabs(d - ring.radius) <= half_diagonal + ring.width / 2.0) {
          list.push_back(static_cast<std::uint32_t>(r) | kRingBit);
        }
      }
    }
  }
  g.first.clear();
  g.items.clear();
  for (const auto& list : cells) {
    g.first.push_back(static_cast<std::uint32_t>(g.items.size()));
    g.items.insert(g.items.end(), list.begin(), list.end());
  }
  g.first.push_back(static_cast<std::uint32_t>(g.items.size()));
}

void CameraRenderer::render(const hal::Pose2& pose, const hal::CameraPosture& posture) noexcept {
  pose_ = pose;
  const hal::CameraPose cam = hal::CameraPose::from_posture(spec_.mount, posture);
  const double s = std::sin(pose.theta);
  const double c = std::cos(pose.theta);
  const Vec3 offset = detail::robot_to_world_direction(s, c, cam.position);
  origin_ = {pose.x + offset.x, pose.y + offset.y, offset.z};
  for (std::size_t i = 0; i < 3; ++i) axes_[i] = detail::robot_to_world_direction(s, c, cam.axes[i]);
  truth_.pose = pose;
  truth_.head = posture.head;
  truth_.body = posture.body;
  compute_obstacle_boxes();
  render_pixels();
  compute_truth();
}

void CameraRenderer::compute_obstacle_boxes() noexcept {
  const hal::CameraIntrinsics& k = spec_.intrinsics;
  const auto box_of = [&](double x0, double y0, double x1, double y1, double z1) {
    ScreenBox box;
    double umin = 1e300, umax = -1e300, vmin = 1e300, vmax = -1e300;
    int behind = 0;
    for (int i = 0; i < 8; ++i) {
      const Vec3 p{(i & 1) != 0 ? x1 : x0, (i & 2) != 0 ? y1 : y0, (i & 4) != 0 ? z1 : 0.0};
      const Vec3 rel = sub(p, origin_);
      const double z = dot(rel, axes_[2]);
      if (z <= 1e-6) {
        ++behind;
        continue;
      }
      const double u = k.fx * dot(rel, axes_[0]) / z + k.cx;
      const double v = k.fy * dot(rel, axes_[1]) / z + k.cy;
      umin = std::min(umin, u);
      umax = std::max(umax, u);
      vmin = std::min(vmin, v);
      vmax = std::max(vmax, v);
    }
    if (behind == 8) return box;  // wholly behind the camera: empty
    if (behind > 0) {             // straddles the camera plane: could cover anything
      return ScreenBox{0, k.width - 1, 0, k.height - 1};
    }
    // Pixel centres are at +0.5; a box covers the pixels whose centres it might contain.
    box.u0 = std::max(0, fast_floor(std::max(umin, -1.0)));
    box.u1 = std::min(k.width - 1, fast_floor(std::min(umax, k.width + 1.0)));
    box.v0 = std::max(0, fast_floor(std::max(vmin, -1.0)));
    box.v1 = std::min(k.height - 1, fast_floor(std::min(vmax, k.height + 1.0)));
    return box;
  };
  for (std::size_t i = 0; i < world_.circles.size(); ++i) {
    const Circle& c = world_.circles[i];
    boxes_[i] = box_of(c.centre.x - c.radius, c.centre.y - c.radius, c.centre.x + c.radius, c.centre.y + c.radius,
                       c.height);
  }
  ScreenBox& ball_box = boxes_.back();
  ball_box = ScreenBox{};
  if (world_.ball) {
    const Ball& b = *world_.ball;
    ball_box = box_of(b.position.x - b.radius, b.position.y - b.radius, b.position.x + b.radius,
                      b.position.y + b.radius, 2.0 * b.radius);
  }
}

void CameraRenderer::render_pixels() noexcept {
  const hal::CameraIntrinsics& k = spec_.intrinsics;
  const int width = k.width;
  const int height = k.height;
  const Lighting& light = world_.lighting;
  const double sun_cos = std::cos(light.sun_angle);
  const double sun_sin = std::sin(light.sun_angle);
  const double texture = light.texture;
  const Vec3 step = scale(1.0 / k.fx, axes_[0]);
  const std::size_t circles = world_.circles.size();
  const std::size_t ball_index = circles;
  const bool has_ball = world_.ball.has_value();
  const Vec3 ball_centre = has_ball ? Vec3{world_.ball->position.x, world_.ball->position.y, world_.ball->radius}
                                    : Vec3{};
  const double ball_radius = has_ball ? world_.ball->radius : 0.0;
  const Grid& g = grid_;
  const double inv_cell = 1.0 / g.cell;
  const std::uint32_t coarse_seed = seed_ ^ 0x51ed270bU;
  const std::uint32_t background_seed = seed_ ^ 0x9e3779b9U;
  ball_pixels_ = 0;
  ball_pixels_shown_ = 0;

  for (int v = 0; v < height; ++v) {
    std::size_t active = 0;
    for (std::size_t i = 0; i < boxes_.size(); ++i) {
      if (v >= boxes_[i].v0 && v <= boxes_[i].v1) row_active_[active++] = static_cast<std::uint32_t>(i);
    }
    const Vec3 base = add(add(axes_[2], scale((v + 0.5 - k.cy) / k.fy, axes_[1])), scale((0.5 - k.cx) / k.fx, axes_[0]));
    std::uint8_t* out = bgr_.data() + static_cast<std::size_t>(v) * static_cast<std::size_t>(width) * 3U;
    PixelLabel* label = labels_.data() + static_cast<std::size_t>(v) * static_cast<std::size_t>(width);
    for (int u = 0; u < width; ++u, out += 3, ++label) {
      const double fu = static_cast<double>(u);
      const Vec3 d{base.x + fu * step.x, base.y + fu * step.y, base.z + fu * step.z};
      double t_best = detail::kNoHit3;
      int hit = kNothing;
      if (d.z < 0.0) {
        t_best = -origin_.z / d.z;
        hit = kGround;
      }
      for (std::size_t a = 0; a < active; ++a) {
        const std::uint32_t i = row_active_[a];
        if (u < boxes_[i].u0 || u > boxes_[i].u1) continue;
        double t = detail::kNoHit3;
        if (i == ball_index) {
          t = detail::ray_sphere(origin_, d, ball_centre, ball_radius);
          if (t < detail::kNoHit3) ++ball_pixels_;
        } else {
          t = detail::ray_cylinder(origin_, d, world_.circles[i]);
        }
        if (t < t_best) {
          t_best = t;
          hit = static_cast<int>(i);
        }
      }

      if (hit == kGround) {
        const double x = origin_.x + t_best * d.x;
        const double y = origin_.y + t_best * d.y;
        const bool on_carpet = x >= world_.min.x && x <= world_.max.x && y >= world_.min.y && y <= world_.max.y;
        if (!on_carpet) {
          const double n = unit(hash2(fast_floor(x * 20.0), fast_floor(y * 20.0), seed_));
          put(out, kFloor, light.brightness * (0.92 + 0.16 * n));
          *label = PixelLabel::kFloor;
          continue;
        }
        bool paint = false;
        const int gx = std::min(g.nx - 1, fast_floor((x - g.x0) * inv_cell));
        const int gy = std::min(g.ny - 1, fast_floor((y - g.y0) * inv_cell));
        const auto cell = static_cast<std::size_t>(gy) * static_cast<std::size_t>(g.nx) + static_cast<std::size_t>(gx);
        for (std::uint32_t j = g.first[cell]; j < g.first[cell + 1] && !paint; ++j) {
          const std::uint32_t item = g.items[j];
          if ((item & kRingBit) != 0) {
            const Ring& ring = world_.rings[item & ~kRingBit];
            const double dist = std::sqrt((x - ring.centre.x) * (x - ring.centre.x) + (y - ring.centre.y) * (y - ring.centre.y));
            paint = std::fabs(dist - ring.radius) <= ring.width / 2.0;
          } else {
            const Marking& mk = world_.markings[item];
            const double half = mk.width / 2.0;
            paint = detail::segment_distance_squared(Vec2{x, y}, mk.a, mk.b) <= half * half;
          }
        }
        // Carpet: fine fibre noise on a 2 cm lattice, a slow 1.5 m mottling, then the sun.
        const double fine = 2.0 * unit(hash2(fast_floor(x * 50.0), fast_floor(y * 50.0), seed_)) - 1.0;
        const double coarse = 2.0 * detail::value_noise(x * (1.0 / 1.5), y * (1.0 / 1.5), coarse_seed) - 1.0;
        const double lit = light.brightness * (1.0 + 0.75 * texture * coarse) * sun_factor(light, sun_cos, sun_sin, x, y);
        if (paint) {
          put(out, kPaint, lit * (1.0 + 0.3 * texture * fine));
          *label = PixelLabel::kMarking;
        } else {
          put(out, kCarpet, lit * (1.0 + texture * fine));
          *label = PixelLabel::kCarpet;
        }
      } else if (hit == kNothing) {
        // Above the horizon: the hall's walls and crowd, blocky variation fixed to the direction.
        const double inv = 1.0 / std::sqrt(dot(d, d));
        const double h1 = unit(hash2(fast_floor(d.x * inv * 40.0), fast_floor(d.y * inv * 40.0), background_seed));
        const double up = d.z * inv;  // 0 at the horizon, 1 straight up
        put(out, kBackground, light.brightness * (0.75 + 0.4 * h1) * (1.0 - 0.35 * up));
        *label = PixelLabel::kBackground;
      } else if (static_cast<std::size_t>(hit) == ball_index) {
        ++ball_pixels_shown_;
        const Vec3 p = add(origin_, scale(t_best, d));
        const double nz = (p.z - ball_centre.z) / ball_radius;  // lit from above
        put(out, kBall, light.brightness * (0.55 + 0.45 * nz));
        *label = PixelLabel::kBall;
      } else {
        const Circle& c = world_.circles[static_cast<std::size_t>(hit)];
        const Vec3 p = add(origin_, scale(t_best, d));
        // Lit from one side (a fixed direction in the world), the top cap fully.
        const double nx = (p.x - c.centre.x) / c.radius;
        const double ny = (p.y - c.centre.y) / c.radius;
        const bool cap = p.z >= c.height - 1e-9;
        const double shade = cap ? 1.0 : 0.85 + 0.15 * (0.6 * nx + 0.8 * ny);
        Colour colour = kObstacle;
        *label = PixelLabel::kObstacle;
        if (c.kind == ObstacleKind::kPost) {
          colour = kPost;
          *label = PixelLabel::kPost;
        }
        if (c.kind == ObstacleKind::kRobot) {
          const double rel = p.z / c.height;
          colour = (!cap && rel >= kJerseyLow && rel <= kJerseyHigh) ? kRobotJersey : kRobotBody;
          *label = PixelLabel::kRobot;
        }
        put(out, colour, light.brightness * shade);
      }
    }
  }
}

}  // namespace ringlet::sim_hal
