// The ground truth of a rendered frame. Lines are sampled about every centimetre along their
// middle; a sample counts as visible when it projects inside the image and nothing (an obstacle or
// the ball) stands between it and the camera. Ground points in front of a camera that is above
// the ground are always below the horizon, so that needs no separate test.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "nao_model.hpp"
#include "render_math.hpp"
#include "ringlet/sim_hal/camera_renderer.hpp"

#include "ringlet/hal/portable_math.hpp"

namespace ringlet::sim_hal {
namespace {

using detail::dot;
using detail::sub;
using hal::Vec3;

constexpr double kSampleSpacing = 0.01;  // m along a line or ring

std::size_t sample_count(double length) noexcept {
  return static_cast<std::size_t>(std::max(1.0, std::ceil(length / kSampleSpacing)));
}

}  // namespace

bool CameraRenderer::sample_visible(const Vec3& ground, hal::Pixel& px) const noexcept {
  const hal::CameraIntrinsics& k = spec_.intrinsics;
  const Vec3 rel = sub(ground, origin_);
  const double z = dot(rel, axes_[2]);
  if (!(z > 1e-9)) return false;
  px.u = k.fx * dot(rel, axes_[0]) / z + k.cx;
  px.v = k.fy * dot(rel, axes_[1]) / z + k.cy;
  if (!(px.u >= 0.0 && px.u < k.width && px.v >= 0.0 && px.v < k.height)) return false;
  // An occluder must cover this pixel, so only obstacles whose screen box holds it are tested.
  const int iu = detail::fast_floor(px.u);
  const int iv = detail::fast_floor(px.v);
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    const ScreenBox& b = boxes_[i];
    if (iu < b.u0 || iu > b.u1 || iv < b.v0 || iv > b.v1) continue;
    // rel runs from the camera to the sample: a hit with t < 1 lies in between.
    if (hit_object(i, origin_, rel) < 1.0) return false;
  }
  return true;
}

void CameraRenderer::compute_truth() noexcept {
  truth_.lines.clear();
  truth_.lines_truncated = false;
  for (std::size_t m = 0; m < world_.markings.size(); ++m) {
    const Marking& mk = world_.markings[m];
    const std::size_t n = sample_count(hal::portable_hypot(mk.b.x - mk.a.x, mk.b.y - mk.a.y));
    bool open = false;
    LineRunTruth run;
    run.marking = m;
    Vec2 last{};
    const auto close = [&]() {
      run.ground_b = hal::to_robot_frame(pose_, last.x, last.y);
      if (truth_.lines.size() < truth_.lines.capacity()) {
        truth_.lines.push_back(run);
      } else {
        truth_.lines_truncated = true;
      }
      open = false;
    };
    for (std::size_t i = 0; i <= n; ++i) {
      const double f = static_cast<double>(i) / static_cast<double>(n);
      const Vec2 p{mk.a.x + f * (mk.b.x - mk.a.x), mk.a.y + f * (mk.b.y - mk.a.y)};
      hal::Pixel px;
      if (sample_visible(Vec3{p.x, p.y, 0.0}, px)) {
        if (!open) {
          open = true;
          run.image_a = px;
          run.ground_a = hal::to_robot_frame(pose_, p.x, p.y);
        }
        run.image_b = px;
        last = p;
      } else if (open) {
        close();
      }
    }
    if (open) close();
  }

  for (std::size_t r = 0; r < world_.rings.size(); ++r) {
    const Ring& ring = world_.rings[r];
    const std::size_t n = sample_count(2.0 * std::numbers::pi * ring.radius);
    // Walk round the ring by rotating one vector: two trig calls per ring, not per sample.
    const double step = 2.0 * std::numbers::pi / static_cast<double>(n);
    const double cs = std::cos(step);
    const double sn = std::sin(step);
    double dx = ring.radius;
    double dy = 0.0;
    std::size_t seen = 0;
    for (std::size_t i = 0; i < n; ++i) {
      hal::Pixel px;
      if (sample_visible(Vec3{ring.centre.x + dx, ring.centre.y + dy, 0.0}, px)) ++seen;
      const double nx = dx * cs - dy * sn;
      dy = dx * sn + dy * cs;
      dx = nx;
    }
    truth_.rings[r] = RingTruth{r, seen > 0, static_cast<double>(seen) / static_cast<double>(n)};
  }

  compute_object_truth();
}

void CameraRenderer::compute_object_truth() noexcept {
  const hal::CameraIntrinsics& k = spec_.intrinsics;
  const auto pixel_box = [](int u0, int u1, int v0, int v1) {
    return u1 < u0 ? ImageBox{} : ImageBox{double(u0), double(v0), double(u1 + 1), double(v1 + 1)};
  };
  const auto project = [&](const Vec3& world_point, hal::Pixel& px) {
    const Vec3 rel = sub(world_point, origin_);
    const double z = dot(rel, axes_[2]);
    if (!(z > 1e-9)) return false;
    px = {k.fx * dot(rel, axes_[0]) / z + k.cx, k.fy * dot(rel, axes_[1]) / z + k.cy};
    return true;
  };
  const std::size_t circles = world_.circles.size();

  truth_.balls.clear();
  for (std::size_t b = 0; b < balls_.size(); ++b) {
    const Ball& ball = balls_[b];
    const ObjectStats& st = stats_[circles + b];
    BallTruth bt;
    bt.present = true;
    bt.position = hal::to_robot_frame(pose_, ball.position.x, ball.position.y);
    bt.distance = hal::portable_hypot(bt.position.x, bt.position.y);
    bt.bearing = std::atan2(bt.position.y, bt.position.x);
    const Vec3 rel = sub(Vec3{ball.position.x, ball.position.y, ball.radius}, origin_);
    const double z = dot(rel, axes_[2]);
    bt.in_front = z > 1e-9;
    if (bt.in_front) {
      bt.image_centre = {k.fx * dot(rel, axes_[0]) / z + k.cx, k.fy * dot(rel, axes_[1]) / z + k.cy};
      bt.image_radius = k.fx * ball.radius / z;
      // The projected disc's share inside the image, counted on a 16 × 16 grid over its box.
      int inside = 0, total = 0;
      for (int j = 0; j < 16; ++j) {
        for (int i = 0; i < 16; ++i) {
          const double du = (i + 0.5) / 8.0 - 1.0, dv = (j + 0.5) / 8.0 - 1.0;
          if (du * du + dv * dv > 1.0) continue;
          ++total;
          const double u = bt.image_centre.u + du * bt.image_radius, v = bt.image_centre.v + dv * bt.image_radius;
          if (u >= 0.0 && u < k.width && v >= 0.0 && v < k.height) ++inside;
        }
      }
      bt.in_image_fraction = total == 0 ? 0.0 : static_cast<double>(inside) / static_cast<double>(total);
    }
    bt.visible = st.shown > 0;
    bt.visible_fraction = st.hits == 0 ? 0.0 : static_cast<double>(st.shown) / static_cast<double>(st.hits);
    bt.pixels = pixel_box(st.hit_u0, st.hit_u1, st.hit_v0, st.hit_v1);
    bt.visible_pixels = pixel_box(st.shown_u0, st.shown_u1, st.shown_v0, st.shown_v1);
    truth_.balls.push_back(bt);
  }
  truth_.ball = world_.ball ? truth_.balls.front() : BallTruth{};

  truth_.robots.clear();
  for (std::size_t i = 0; i < circles; ++i) {
    const Circle& c = world_.circles[i];
    if (c.kind != ObstacleKind::kRobot) continue;
    const ObjectStats& st = stats_[i];
    const RobotFrame& f = robot_frames_[i];
    RobotTruth rt;
    rt.circle = i;
    rt.foot = hal::to_robot_frame(pose_, c.centre.x, c.centre.y);
    rt.distance = hal::portable_hypot(rt.foot.x, rt.foot.y);
    rt.bearing = std::atan2(rt.foot.y, rt.foot.x);
    rt.heading = f.heading;
    rt.team = f.team;
    hal::Pixel px;
    rt.in_front = project(Vec3{c.centre.x, c.centre.y, 0.0}, px);
    // The whole body's box: the NAO's part boxes (or the cylinder's corners) projected.
    double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
    bool all_in_front = true;
    const auto add_point = [&](const Vec3& p) {
      if (!project(p, px)) {
        all_in_front = false;
        return;
      }
      u0 = std::min(u0, px.u);
      u1 = std::max(u1, px.u);
      v0 = std::min(v0, px.v);
      v1 = std::max(v1, px.v);
    };
    if (nao_robot(i)) {
      for (const Vec3& q : detail::nao_hull_points()) {
        const Vec3 local = detail::scale(f.scale, q);
        const Vec3 w = detail::robot_to_world_direction(f.sin_h, f.cos_h, local);
        add_point(Vec3{c.centre.x + w.x, c.centre.y + w.y, w.z});
      }
    } else {
      for (int n = 0; n < 8; ++n) {
        const double a = static_cast<double>(n) * (std::numbers::pi / 4.0);
        for (const double h : {0.0, c.height}) {
          add_point(Vec3{c.centre.x + c.radius * std::cos(a), c.centre.y + c.radius * std::sin(a), h});
        }
      }
    }
    if (all_in_front && u1 >= u0) rt.box = ImageBox{u0, v0, u1, v1};
    rt.pixels = pixel_box(st.hit_u0, st.hit_u1, st.hit_v0, st.hit_v1);
    rt.visible_pixels = pixel_box(st.shown_u0, st.shown_u1, st.shown_v0, st.shown_v1);
    rt.visible = st.shown > 0;
    rt.visible_fraction = st.hits == 0 ? 0.0 : static_cast<double>(st.shown) / static_cast<double>(st.hits);
    truth_.robots.push_back(rt);
  }
}

}  // namespace ringlet::sim_hal
