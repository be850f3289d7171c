// The ground truth of a rendered frame. Lines are sampled about every centimetre along their
// middle; a sample counts as visible when it projects inside the image and nothing (an obstacle or
// the ball) stands between it and the camera. Ground points in front of a camera that is above
// the ground are always below the horizon, so that needs no separate test.
#include <cmath>
#include <numbers>

#include "render_math.hpp"
#include "ringlet/sim_hal/camera_renderer.hpp"

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
    double t = detail::kNoHit3;
    if (i < world_.circles.size()) {
      t = detail::ray_cylinder(origin_, rel, world_.circles[i]);
    } else if (world_.ball) {
      const Ball& ball = *world_.ball;
      t = detail::ray_sphere(origin_, rel, Vec3{ball.position.x, ball.position.y, ball.radius}, ball.radius);
    }
    if (t < 1.0) return false;
  }
  return true;
}

void CameraRenderer::compute_truth() noexcept {
  truth_.lines.clear();
  truth_.lines_truncated = false;
  for (std::size_t m = 0; m < world_.markings.size(); ++m) {
    const Marking& mk = world_.markings[m];
    const std::size_t n = sample_count(std::hypot(mk.b.x - mk.a.x, mk.b.y - mk.a.y));
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

  BallTruth& bt = truth_.ball;
  bt = BallTruth{};
  if (world_.ball) {
    const Ball& ball = *world_.ball;
    const hal::CameraIntrinsics& k = spec_.intrinsics;
    bt.present = true;
    bt.position = hal::to_robot_frame(pose_, ball.position.x, ball.position.y);
    const Vec3 rel = sub(Vec3{ball.position.x, ball.position.y, ball.radius}, origin_);
    const double z = dot(rel, axes_[2]);
    bt.in_front = z > 1e-9;
    if (bt.in_front) {
      bt.image_centre = {k.fx * dot(rel, axes_[0]) / z + k.cx, k.fy * dot(rel, axes_[1]) / z + k.cy};
      bt.image_radius = k.fx * ball.radius / z;
    }
    bt.visible = ball_pixels_shown_ > 0;
    bt.visible_fraction =
        ball_pixels_ == 0 ? 0.0 : static_cast<double>(ball_pixels_shown_) / static_cast<double>(ball_pixels_);
  }
}

}  // namespace ringlet::sim_hal
