// The per-pixel part of the simulated camera. Speed comes from three things: the viewing ray is
// linear in u, so a row needs one multiply-add per component per pixel and no trig; obstacles are
// only tested inside their projected bounding boxes; markings are looked up in a coarse grid of
// the ground instead of being tested one by one.
#include "ringlet/sim_hal/camera_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "camera_shading.hpp"
#include "nao_model.hpp"
#include "render_math.hpp"
#include "vec2_math.hpp"

#include "ringlet/hal/portable_math.hpp"

namespace ringlet::sim_hal {
namespace {

using detail::add;
using detail::dot;
using detail::fast_floor;
using detail::hash2;
using detail::scale;
using detail::sub;
using detail::to_byte;
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
      labels_(static_cast<std::size_t>(spec.intrinsics.width) * static_cast<std::size_t>(spec.intrinsics.height)) {
  build_grid();
  setup_objects();
  truth_.lines.reserve(world_.markings.size() * (world_.circles.size() + balls_.size() + 2) + 16);
  truth_.rings.resize(world_.rings.size());
}

void CameraRenderer::setup_objects() {
  if (world_.ball) balls_.push_back(*world_.ball);
  balls_.insert(balls_.end(), world_.extra_balls.begin(), world_.extra_balls.end());
  const std::size_t objects = world_.circles.size() + balls_.size();
  boxes_.resize(objects);
  row_active_.resize(objects);
  stats_.resize(objects);
  const auto& k = spec_.intrinsics;
  line_buffer_.resize(static_cast<std::size_t>(std::max(k.width, k.height)) * 3U);
  // Each robot faces its own way and wears one of the jerseys, both fixed by the seed.
  robot_frames_.resize(world_.circles.size());
  std::size_t robots = 0;
  for (std::size_t i = 0; i < world_.circles.size(); ++i) {
    const Circle& c = world_.circles[i];
    RobotFrame& f = robot_frames_[i];
    const std::uint32_t h = hash2(static_cast<int>(i), 0x6e616f, seed_);
    f.heading = hal::wrap_angle(2.0 * std::numbers::pi * unit(h));
    f.sin_h = std::sin(f.heading);
    f.cos_h = std::cos(f.heading);
    f.scale = c.height / detail::kNaoHeight;
    f.team = static_cast<std::uint8_t>(hash2(static_cast<int>(i), 0x7465616d, seed_) % detail::kJerseyCount);
    if (c.kind == ObstacleKind::kRobot) ++robots;
  }
  // Each ball's pattern is turned by three angles of its own.
  ball_axes_.resize(balls_.size());
  for (std::size_t b = 0; b < balls_.size(); ++b) {
    const double a = 2.0 * std::numbers::pi * unit(hash2(static_cast<int>(b), 1, seed_ ^ 0xba11U));
    const double e = 2.0 * std::numbers::pi * unit(hash2(static_cast<int>(b), 2, seed_ ^ 0xba11U));
    const double r = 2.0 * std::numbers::pi * unit(hash2(static_cast<int>(b), 3, seed_ ^ 0xba11U));
    const double ca = std::cos(a), sa = std::sin(a), ce = std::cos(e), se = std::sin(e), cr = std::cos(r), sr = std::sin(r);
    // Rz(a) · Rx(e) · Rz(r), rows = the ball's axes in the world.
    ball_axes_[b] = {Vec3{ca * cr - sa * ce * sr, -ca * sr - sa * ce * cr, sa * se},
                     Vec3{sa * cr + ca * ce * sr, -sa * sr + ca * ce * cr, -ca * se},
                     Vec3{se * sr, se * cr, ce}};
  }
  truth_.balls.reserve(balls_.size());
  truth_.robots.reserve(robots);
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
        const double d = hal::portable_hypot(centre.x - ring.centre.x, centre.y - ring.centre.y);
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
  compute_camera_gains();
  compute_obstacle_boxes();
  render_pixels();
  compute_truth();
  if (world_.look.style == LookStyle::kSpl) post_process();
  ++frame_;
}

bool CameraRenderer::nao_robot(std::size_t circle) const noexcept {
  return world_.look.style == LookStyle::kSpl && world_.circles[circle].kind == ObstacleKind::kRobot;
}

double CameraRenderer::hit_object(std::size_t i, const Vec3& o, const Vec3& d) const noexcept {
  const std::size_t circles = world_.circles.size();
  if (i >= circles) {
    const Ball& b = balls_[i - circles];
    return detail::ray_sphere(o, d, Vec3{b.position.x, b.position.y, b.radius}, b.radius);
  }
  if (!nao_robot(i)) return detail::ray_cylinder(o, d, world_.circles[i]);
  detail::NaoHit hit;
  detail::ray_nao(detail::to_robot_model(world_.circles[i], robot_frames_[i].sin_h, robot_frames_[i].cos_h,
                                         robot_frames_[i].scale, o, true),
                  detail::to_robot_model(world_.circles[i], robot_frames_[i].sin_h, robot_frames_[i].cos_h,
                                         robot_frames_[i].scale, d, false),
                  hit);
  return hit.t;
}

void CameraRenderer::compute_camera_gains() noexcept {
  const CameraLook& look = world_.look;
  gain_ = {1.0, 1.0, 1.0};
  if (look.style != LookStyle::kSpl) return;
  // Auto exposure and white balance hunt slowly: smooth noise over the frame count.
  const double x = static_cast<double>(frame_) / look.drift_frames;
  const auto drift = [&](std::uint32_t salt, double amount) {
    return 1.0 + amount * (2.0 * detail::value_noise(x, 0.5, seed_ ^ salt) - 1.0);
  };
  const double e = look.exposure * drift(0xe1U, look.drift);
  gain_[1] = e;
  gain_[2] = e * look.white_red * drift(0x3edU, 0.5 * look.drift);
  gain_[0] = e * look.white_blue * drift(0xb1eU, 0.5 * look.drift);
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
    // A NAO's arms reach a little past a 0.15 m circle: box the larger of the two.
    const double r = nao_robot(i) ? std::max(c.radius, detail::kNaoReach * robot_frames_[i].scale) : c.radius;
    boxes_[i] = box_of(c.centre.x - r, c.centre.y - r, c.centre.x + r, c.centre.y + r, c.height);
  }
  for (std::size_t b = 0; b < balls_.size(); ++b) {
    const Ball& ball = balls_[b];
    boxes_[world_.circles.size() + b] = box_of(ball.position.x - ball.radius, ball.position.y - ball.radius,
                                               ball.position.x + ball.radius, ball.position.y + ball.radius,
                                               2.0 * ball.radius);
  }
}

void CameraRenderer::render_pixels() noexcept {
  const hal::CameraIntrinsics& k = spec_.intrinsics;
  const int width = k.width;
  const int height = k.height;
  const Lighting& light = world_.lighting;
  const bool spl = world_.look.style == LookStyle::kSpl;
  const detail::SplShader shader(world_.look, light, seed_, gain_);
  const double sun_cos = std::cos(light.sun_angle);
  const double sun_sin = std::sin(light.sun_angle);
  const double texture = light.texture;
  const Vec3 step = scale(1.0 / k.fx, axes_[0]);
  const std::size_t circles = world_.circles.size();
  const Grid& g = grid_;
  const double inv_cell = 1.0 / g.cell;
  const std::uint32_t coarse_seed = seed_ ^ 0x51ed270bU;
  const std::uint32_t background_seed = seed_ ^ 0x9e3779b9U;
  for (ObjectStats& st : stats_) st = ObjectStats{};
  const auto extend = [](int& lo, int& hi, int x) {
    if (hi < lo) {
      lo = x;
      hi = x;
    } else {
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  };

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
      detail::NaoHit nao_best;
      if (d.z < 0.0) {
        t_best = -origin_.z / d.z;
        hit = kGround;
      }
      for (std::size_t a = 0; a < active; ++a) {
        const std::uint32_t i = row_active_[a];
        if (u < boxes_[i].u0 || u > boxes_[i].u1) continue;
        double t = detail::kNoHit3;
        detail::NaoHit nao;
        if (i < circles && nao_robot(i)) {
          const RobotFrame& f = robot_frames_[i];
          const Circle& c = world_.circles[i];
          detail::ray_nao(detail::to_robot_model(c, f.sin_h, f.cos_h, f.scale, origin_, true),
                          detail::to_robot_model(c, f.sin_h, f.cos_h, f.scale, d, false), nao);
          t = nao.t;
        } else {
          t = hit_object(i, origin_, d);
        }
        if (t < detail::kNoHit3) {
          ObjectStats& st = stats_[i];
          ++st.hits;
          extend(st.hit_u0, st.hit_u1, u);
          extend(st.hit_v0, st.hit_v1, v);
        }
        if (t < t_best) {
          t_best = t;
          hit = static_cast<int>(i);
          nao_best = nao;
        }
      }
      if (hit >= 0) {
        ObjectStats& st = stats_[static_cast<std::size_t>(hit)];
        ++st.shown;
        extend(st.shown_u0, st.shown_u1, u);
        extend(st.shown_v0, st.shown_v1, v);
      }

      if (hit == kGround) {
        const double x = origin_.x + t_best * d.x;
        const double y = origin_.y + t_best * d.y;
        const bool on_carpet = x >= world_.min.x && x <= world_.max.x && y >= world_.min.y && y <= world_.max.y;
        if (!on_carpet) {
          *label = PixelLabel::kFloor;
          if (spl) {
            shader.floor(out, x, y);
            continue;
          }
          const double n = unit(hash2(fast_floor(x * 20.0), fast_floor(y * 20.0), seed_));
          put(out, kFloor, light.brightness * (0.92 + 0.16 * n));
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
        *label = paint ? PixelLabel::kMarking : PixelLabel::kCarpet;
        if (spl) {
          shader.ground(out, x, y, paint);
          continue;
        }
        // Carpet: fine fibre noise on a 2 cm lattice, a slow 1.5 m mottling, then the sun.
        const double fine = 2.0 * unit(hash2(fast_floor(x * 50.0), fast_floor(y * 50.0), seed_)) - 1.0;
        const double coarse = 2.0 * detail::value_noise(x * (1.0 / 1.5), y * (1.0 / 1.5), coarse_seed) - 1.0;
        const double lit = light.brightness * (1.0 + 0.75 * texture * coarse) * sun_factor(light, sun_cos, sun_sin, x, y);
        if (paint) {
          put(out, kPaint, lit * (1.0 + 0.3 * texture * fine));
        } else {
          put(out, kCarpet, lit * (1.0 + texture * fine));
        }
      } else if (hit == kNothing) {
        *label = PixelLabel::kBackground;
        if (spl) {
          shader.background(out, d);
          continue;
        }
        // Above the horizon: the hall's walls and crowd, blocky variation fixed to the direction.
        const double inv = 1.0 / std::sqrt(dot(d, d));
        const double h1 = unit(hash2(fast_floor(d.x * inv * 40.0), fast_floor(d.y * inv * 40.0), background_seed));
        const double up = d.z * inv;  // 0 at the horizon, 1 straight up
        put(out, kBackground, light.brightness * (0.75 + 0.4 * h1) * (1.0 - 0.35 * up));
      } else if (static_cast<std::size_t>(hit) >= circles) {
        *label = PixelLabel::kBall;
        const std::size_t b = static_cast<std::size_t>(hit) - circles;
        const Ball& ball = balls_[b];
        const Vec3 centre{ball.position.x, ball.position.y, ball.radius};
        const Vec3 p = add(origin_, scale(t_best, d));
        if (spl || world_.look.ball == BallLook::kBlackWhite) {
          const Vec3 n = scale(1.0 / ball.radius, sub(p, centre));
          shader.ball(out, p, n, ball_axes_[b], world_.look.ball == BallLook::kBlackWhite, spl);
          continue;
        }
        const double nz = (p.z - centre.z) / ball.radius;  // lit from above
        put(out, kBall, light.brightness * (0.55 + 0.45 * nz));
      } else {
        const Circle& c = world_.circles[static_cast<std::size_t>(hit)];
        const Vec3 p = add(origin_, scale(t_best, d));
        *label = c.kind == ObstacleKind::kPost ? PixelLabel::kPost
                 : c.kind == ObstacleKind::kRobot ? PixelLabel::kRobot
                                                  : PixelLabel::kObstacle;
        if (spl) {
          if (nao_robot(static_cast<std::size_t>(hit))) {
            const RobotFrame& f = robot_frames_[static_cast<std::size_t>(hit)];
            shader.nao(out, p, detail::robot_to_world_direction(f.sin_h, f.cos_h, nao_best.normal), nao_best.material,
                       f.team);
          } else {
            shader.cylinder(out, p, c);
          }
          continue;
        }
        // Lit from one side (a fixed direction in the world), the top cap fully.
        const double nx = (p.x - c.centre.x) / c.radius;
        const double ny = (p.y - c.centre.y) / c.radius;
        const bool cap = p.z >= c.height - 1e-9;
        const double shade = cap ? 1.0 : 0.85 + 0.15 * (0.6 * nx + 0.8 * ny);
        Colour colour = kObstacle;
        if (c.kind == ObstacleKind::kPost) colour = kPost;
        if (c.kind == ObstacleKind::kRobot) {
          const double rel = p.z / c.height;
          colour = (!cap && rel >= kJerseyLow && rel <= kJerseyHigh) ? kRobotJersey : kRobotBody;
        }
        put(out, colour, light.brightness * shade);
      }
    }
  }
}

}  // namespace ringlet::sim_hal
