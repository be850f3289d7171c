#include "ringlet/vision/ball.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ringlet/hal/portable_math.hpp"

namespace ringlet::vision {

BallDetector::BallDetector(const BallParams& params, int width, int height)
    : params_(params),
      width_(std::max(width, 0)),
      height_(std::max(height, 0)),
      stamp_(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), 0),
      stack_(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_)) {}

BallDetection BallDetector::detect(const ClassImage& classes, const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
                                   int seed_stride_override) noexcept {
  BallDetection best;
  if (classes.width() != width_ || classes.height() != height_) return best;
  if (++current_ == 0) {  // wrapped: clear once every 65535 frames
    std::fill(stamp_.begin(), stamp_.end(), std::uint16_t{0});
    current_ = 1;
  }
  const int s = classes.step();
  const int wanted = seed_stride_override > 0 ? seed_stride_override : params_.seed_stride;
  const int stride = std::max(s, (std::max(wanted, 1) + s - 1) / s * s);
  const int top = classes.first_row();
  const auto w = static_cast<std::size_t>(width_);
  const auto is_ball = [&](int x, int y) { return classes.at(x, y) == ColourClass::kBall; };
  double best_score = 0.0;
  int blobs_grown = 0;  // capped at max_blobs: a frame full of ball-coloured noise stays bounded

  for (int y0 = top; y0 < height_ && blobs_grown < params_.max_blobs; y0 += stride) {
    for (int x0 = 0; x0 < width_ && blobs_grown < params_.max_blobs; x0 += stride) {
      const std::size_t seed = static_cast<std::size_t>(y0) * w + static_cast<std::size_t>(x0);
      if (stamp_[seed] == current_ || !is_ball(x0, y0)) continue;
      ++blobs_grown;
      // Flood fill over the sampled grid.
      std::size_t top_of_stack = 0;
      stack_[top_of_stack++] = static_cast<std::int32_t>(seed);
      stamp_[seed] = current_;
      std::int64_t n = 0, sx = 0, sy = 0;
      int min_x = x0, max_x = x0, min_y = y0, max_y = y0;
      while (top_of_stack > 0) {
        const auto i = static_cast<std::size_t>(stack_[--top_of_stack]);
        const int x = static_cast<int>(i % w);
        const int y = static_cast<int>(i / w);
        ++n;
        sx += x;
        sy += y;
        min_x = std::min(min_x, x);
        max_x = std::max(max_x, x);
        min_y = std::min(min_y, y);
        max_y = std::max(max_y, y);
        const int nx[4] = {x - s, x + s, x, x};
        const int ny[4] = {y, y, y - s, y + s};
        for (int d = 0; d < 4; ++d) {
          if (nx[d] < 0 || nx[d] >= width_ || ny[d] < top || ny[d] >= height_) continue;
          const std::size_t j = static_cast<std::size_t>(ny[d]) * w + static_cast<std::size_t>(nx[d]);
          if (stamp_[j] == current_ || !is_ball(nx[d], ny[d])) continue;
          stamp_[j] = current_;
          if (top_of_stack < stack_.size()) stack_[top_of_stack++] = static_cast<std::int32_t>(j);
        }
      }
      const auto pixels = static_cast<int>(n * s * s);
      if (pixels < params_.min_pixels) continue;
      const double ex = static_cast<double>(max_x - min_x + s);
      const double ey = static_cast<double>(max_y - min_y + s);
      const double radius = std::max(ex, ey) / 2.0;
      const hal::Pixel centre{static_cast<double>(sx) / static_cast<double>(n) + 0.5 * s,
                              static_cast<double>(sy) / static_cast<double>(n) + 0.5 * s};
      // Roundness: aspect of the box and how much of the disc of that radius is filled (a disc
      // fills 1, a full box 4/π, a thin stroke little).
      const double aspect = std::min(ex, ey) / std::max(ex, ey);
      const double fill = static_cast<double>(pixels) / (std::numbers::pi * radius * radius);
      const double fill_score = std::clamp(1.0 - std::abs(1.0 - fill), 0.0, 1.0);
      const double size_score = std::min(1.0, radius / 4.0);
      BallDetection d;
      d.seen = true;
      d.centre = centre;
      d.radius_px = radius;
      d.pixels = pixels;
      double consistency = 1.0;
      const hal::Vec3 ray = hal::pixel_ray(k, pose, centre);
      if (ray.z < -1e-12 && pose.position.z > params_.radius_m) {
        const double t = (params_.radius_m - pose.position.z) / ray.z;
        d.ground = {pose.position.x + t * ray.x, pose.position.y + t * ray.y};
        d.ground_valid = true;
        d.distance_m = hal::portable_hypot(d.ground.x, d.ground.y);
        d.bearing_rad = std::atan2(d.ground.y, d.ground.x);
        // The radius a ball there would have in the image.
        const double depth = t * hal::portable_hypot(ray.x, ray.y, ray.z);
        const double expected = k.fx * params_.radius_m / std::max(depth, 1e-6);
        const double ratio = radius / expected;
        consistency = std::clamp(std::min(ratio, 1.0 / ratio), 0.0, 1.0);
      } else {
        consistency = 0.2;  // above the ball plane: cannot be the ball on the ground
      }
      d.confidence = std::clamp(aspect * fill_score * size_score * consistency, 0.0, 1.0);
      const double score = d.confidence * std::sqrt(static_cast<double>(pixels));
      if (score > best_score) {
        best_score = score;
        best = d;
      }
    }
  }
  return best;
}

}  // namespace ringlet::vision
