// Black-and-white ball: size-checked non-field runs, verified by HOG + SVM (bw_ball.hpp).
#include "ringlet/vision/bw_ball.hpp"

#include <algorithm>
#include <cmath>

namespace ringlet::vision {
namespace {

bool non_field(const ClassImage& c, int x, int y) noexcept { return c.at(x, y) != ColourClass::kField; }

// From sampled row y (on column x), the first and last sampled rows of the non-field run through
// it, at most `reach` px away each way; [top, bottom] inclusive.
void vertical_extent(const ClassImage& c, int x, int y, int reach, int& top, int& bottom) noexcept {
  const int s = c.step();
  top = y;
  bottom = y;
  while (top - s >= c.first_row() && y - (top - s) <= reach && non_field(c, x, top - s)) top -= s;
  while (bottom + s < c.height() && (bottom + s) - y <= reach && non_field(c, x, bottom + s)) bottom += s;
}

void horizontal_extent(const ClassImage& c, int x, int y, int reach, int& left, int& right) noexcept {
  const int s = c.step();
  left = x;
  right = x;
  while (left - s >= 0 && x - (left - s) <= reach && non_field(c, left - s, y)) left -= s;
  while (right + s < c.width() && (right + s) - x <= reach && non_field(c, right + s, y)) right += s;
}

double match(double extent, double expected) noexcept {
  if (extent <= 0.0 || expected <= 0.0) return 0.0;
  return std::min(extent, expected) / std::max(extent, expected);
}

}  // namespace

WindowPlacement ball_window(const BwBallParams& p, const HogParams& hog, const hal::Pixel& centre,
                            double radius_px) noexcept {
  const double side = p.window_diameters * 2.0 * radius_px;
  return {centre.u - 0.5 * side, centre.v - 0.5 * side, side / static_cast<double>(hog.window_width)};
}

double BwBallDetector::expected_radius_px(const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
                                          const hal::Pixel& px, hal::RobotPoint* ground) const noexcept {
  const hal::Vec3 ray = hal::pixel_ray(k, pose, px);
  if (!(ray.z < -1e-12) || pose.position.z <= params_.radius_m) return 0.0;
  const double t = (params_.radius_m - pose.position.z) / ray.z;
  const double depth = t * std::hypot(ray.x, ray.y, ray.z);
  if (ground != nullptr) *ground = {pose.position.x + t * ray.x, pose.position.y + t * ray.y};
  return k.fx * params_.radius_m / std::max(depth, 1e-6);
}

void BwBallDetector::add(const Candidate& c) noexcept {
  for (std::size_t i = 0; i < count_; ++i) {
    Candidate& o = cands_[i];
    const double reach = params_.merge_radii * std::max(o.radius, c.radius);
    if (std::abs(o.centre.u - c.centre.u) <= reach && std::abs(o.centre.v - c.centre.v) <= reach) {
      if (c.extent > o.extent) o = c;
      return;
    }
  }
  if (count_ < cands_.size()) {
    cands_[count_++] = c;
    return;
  }
  // Full: replace the worst if this one is better.
  auto worst = std::min_element(cands_.begin(), cands_.end(),
                                [](const Candidate& a, const Candidate& b) { return a.extent < b.extent; });
  if (worst->extent < c.extent) *worst = c;
}

void BwBallDetector::detect(const ClassImage& classes, const hal::FrameView& frame, const hal::CameraIntrinsics& k,
                            const hal::CameraPose& pose, int stride, HogClassifier* classifier, int max_verified,
                            const Deadline& deadline, BallList& out) noexcept {
  out = BallList{};
  count_ = 0;
  const int s = classes.step();
  const int col_stride = std::max(s, (std::max(stride, 1) + s - 1) / s * s);
  const int first = classes.first_row();
  const int h = classes.height();
  const auto consider = [&](int x, double cy_guess) {
    const double r = expected_radius_px(k, pose, {x + 0.5 * s, cy_guess});
    if (r < params_.min_radius_px) return;
    const double d = 2.0 * r;
    const int reach = static_cast<int>(std::ceil(params_.max_extent * d)) + s;
    int top = 0, bottom = 0, left = 0, right = 0;
    const int yc = std::clamp(first + (static_cast<int>(cy_guess) - first) / s * s, first, h - 1);
    if (!non_field(classes, x, yc)) return;
    horizontal_extent(classes, x, yc, reach, left, right);
    const double width = right - left + s;
    const int xc = left + (right - left) / 2 / s * s;
    double cx = xc + 0.5 * s;
    if (width > params_.max_extent * d) cx = x + 0.5 * s;  // wider than a ball (a line): keep the column
    const int xs = width > params_.max_extent * d ? x : xc;
    vertical_extent(classes, xs, yc, reach, top, bottom);
    const double height = bottom - top + s;
    double cy = 0.5 * (top + bottom + s);
    if (height > params_.max_extent * d) cy = cy_guess;
    const double r2 = expected_radius_px(k, pose, {cx, cy});
    if (r2 < params_.min_radius_px) return;
    const double e = match(std::min(width, params_.max_extent * 2.0 * r2), 2.0 * r2) *
                     match(std::min(height, params_.max_extent * 2.0 * r2), 2.0 * r2);
    add({{cx, cy}, r2, e});
  };

  for (int x = 0; x < classes.width(); x += col_stride) {
    int run_start = -1;
    for (int y = first; y <= h; y += s) {
      const bool nf = y < h && non_field(classes, x, y);
      if (nf && run_start < 0) run_start = y;
      if (nf || run_start < 0) continue;
      // Run [run_start, y) ended.
      const double len = y - run_start;
      const double mid = 0.5 * (run_start + y);
      const double r = expected_radius_px(k, pose, {x + 0.5 * s, mid});
      if (r >= params_.min_radius_px) {
        const double d = 2.0 * r;
        if (len >= params_.min_extent * d && len <= params_.max_extent * d) {
          consider(x, mid);
        } else if (len > params_.max_extent * d && y < h) {
          // Too long: a ball may stand in front of whatever continues above it.
          const double rb = expected_radius_px(k, pose, {x + 0.5 * s, y - r});
          if (rb >= params_.min_radius_px) consider(x, y - rb);
        }
      }
      run_start = -1;
    }
  }
  out.candidates = static_cast<int>(count_);
  // Rank by extent match; insertion sort (stable, and std::stable_sort may allocate a buffer).
  for (std::size_t i = 1; i < count_; ++i) {
    const Candidate c = cands_[i];
    std::size_t j = i;
    for (; j > 0 && cands_[j - 1].extent < c.extent; --j) cands_[j] = cands_[j - 1];
    cands_[j] = c;
  }

  const auto fill = [&](const Candidate& c, BallDetection& b) {
    b.seen = true;
    b.centre = c.centre;
    b.radius_px = c.radius;
    b.pixels = static_cast<int>(3.14159265358979 * c.radius * c.radius);
    hal::RobotPoint g{};
    if (expected_radius_px(k, pose, c.centre, &g) > 0.0) {
      b.ground = g;
      b.ground_valid = true;
      b.distance_m = std::hypot(g.x, g.y);
      b.bearing_rad = std::atan2(g.y, g.x);
    }
  };

  const bool use_classifier = classifier != nullptr && max_verified > 0;
  if (!use_classifier) {
    if (count_ > 0) {
      BallDetection& b = out.balls[0];
      fill(cands_[0], b);
      b.confidence = 0.3 * cands_[0].extent;
      out.count = 1;
    }
    return;
  }
  const double threshold = classifier->model().threshold();
  const std::size_t n = std::min(count_, static_cast<std::size_t>(max_verified));
  for (std::size_t i = 0; i < n; ++i) {
    if (deadline.expired()) {
      out.classifications_cut = static_cast<int>(n - i);
      break;
    }
    const Candidate& c = cands_[i];
    const WindowPlacement w = ball_window(params_, classifier->model().params(), c.centre, c.radius);
    const double score = classifier->score_window(frame, w.left, w.top, w.scale);
    ++out.classified;
    if (score < threshold) continue;
    BallDetection b;
    fill(c, b);
    b.verified = true;
    b.score = score;
    b.confidence = svm_confidence(score, threshold);
    // Insert by score, keeping at most kMaxBalls.
    std::size_t at = out.count;
    while (at > 0 && out.balls[at - 1].score < score) --at;
    if (at >= kMaxBalls) continue;
    const std::size_t last = std::min(out.count, kMaxBalls - 1);
    for (std::size_t j = last; j > at; --j) out.balls[j] = out.balls[j - 1];
    out.balls[at] = b;
    out.count = std::min(out.count + 1, kMaxBalls);
  }
}

}  // namespace ringlet::vision
