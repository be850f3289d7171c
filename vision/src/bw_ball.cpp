// Black-and-white ball: size-checked non-field runs, verified by HOG + SVM (bw_ball.hpp).
#include "ringlet/vision/bw_ball.hpp"

#include <algorithm>
#include <cmath>

#include "ringlet/hal/portable_math.hpp"
#include "ringlet/vision/fit.hpp"

namespace ringlet::vision {
namespace {

bool non_field(const ClassImage& c, int x, int y) noexcept { return c.at(x, y) != ColourClass::kField; }

// One expected radius (BallPlane::radius_px) costs about as much as this many ball samples:
// BM_BallRadius over BM_Ball's per-sample time in the same run (9.3 ns against 76.4 us / 18k =
// 4.2 ns; through a ray per call, before BallPlane, 34.4 ns against 4.7 ns, counted as 7). The
// detector takes one at every non-field run's end.
constexpr long kRadiusSamples = 2;

// From sampled row y (on column x), the first and last sampled rows of the non-field run through
// it, at most `reach` px away each way; [top, bottom] inclusive. Returns the samples read.
long vertical_extent(const ClassImage& c, int x, int y, int reach, int& top, int& bottom) noexcept {
  const int s = c.step();
  top = y;
  bottom = y;
  while (top - s >= c.first_row() && y - (top - s) <= reach && non_field(c, x, top - s)) top -= s;
  while (bottom + s < c.height() && (bottom + s) - y <= reach && non_field(c, x, bottom + s)) bottom += s;
  return (bottom - top) / s + 2;
}

long horizontal_extent(const ClassImage& c, int x, int y, int reach, int& left, int& right) noexcept {
  const int s = c.step();
  left = x;
  right = x;
  while (left - s >= 0 && x - (left - s) <= reach && non_field(c, left - s, y)) left -= s;
  while (right + s < c.width() && (right + s) - x <= reach && non_field(c, right + s, y)) right += s;
  return (right - left) / s + 2;
}

constexpr int kContrastGrid = 6;  // 6 × 6 samples, those inside 0.7 r (28) read
constexpr long kContrastSamples = kContrastGrid * kContrastGrid;
// Indices 0..15: the outline's points are all used, in ray order.
constexpr std::array<int, 16> kFirstSixteen{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};

// 16 unit directions, 22.5° apart (literals: the same on every host).
constexpr double kC1 = 0.92387953251128674, kC2 = 0.70710678118654757, kC3 = 0.38268343236508978;
constexpr std::array<std::array<double, 2>, 16> kRays{{{1, 0}, {kC1, kC3}, {kC2, kC2}, {kC3, kC1},
                                                       {0, 1}, {-kC3, kC1}, {-kC2, kC2}, {-kC1, kC3},
                                                       {-1, 0}, {-kC1, -kC3}, {-kC2, -kC2}, {-kC3, -kC1},
                                                       {0, -1}, {kC3, -kC1}, {kC2, -kC2}, {kC1, -kC3}}};

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

BallPlane::BallPlane(const hal::CameraIntrinsics& k, const hal::CameraPose& pose, double radius_m) noexcept
    : pose_(pose),
      cx_(k.cx),
      cy_(k.cy),
      inv_fx_(1.0 / k.fx),
      inv_fy_(1.0 / k.fy),
      height_(radius_m - pose.position.z),
      scale_(k.fx * radius_m / (radius_m - pose.position.z)),
      max_radius_(k.fx * radius_m / 1e-6),
      above_(pose.position.z > radius_m) {}

hal::Vec3 BallPlane::normalised(const hal::Pixel& px) const noexcept {
  return {(px.u - cx_) * inv_fx_, (px.v - cy_) * inv_fy_, 1.0};
}

double BallPlane::radius_px(const hal::Pixel& px) const noexcept {
  const hal::Vec3 n = normalised(px);
  const auto& a = pose_.axes;
  const double ray_z = a[0].z * n.x + a[1].z * n.y + a[2].z;
  if (!(ray_z < -1e-12) || !above_) return 0.0;
  // fx·R / depth with depth = (R − z)·|n| / ray_z; both signs negative.
  return std::min(scale_ * ray_z / std::sqrt(n.x * n.x + n.y * n.y + 1.0), max_radius_);
}

bool BallPlane::ground(const hal::Pixel& px, hal::RobotPoint& at) const noexcept {
  const hal::Vec3 ray = pose_.to_robot_direction(normalised(px));
  if (!(ray.z < -1e-12) || !above_) return false;
  const double t = height_ / ray.z;
  at = {pose_.position.x + t * ray.x, pose_.position.y + t * ray.y};
  return true;
}

double BwBallDetector::expected_radius_px(const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
                                          const hal::Pixel& px, hal::RobotPoint* ground) const noexcept {
  const BallPlane plane(k, pose, params_.radius_m);
  if (ground != nullptr) static_cast<void>(plane.ground(px, *ground));
  return plane.radius_px(px);
}

BwBallDetector::Outline BwBallDetector::fit_outline(const ClassImage& classes, const hal::Pixel& centre, double radius) noexcept {
  const int s = classes.step();
  const int first = classes.first_row();
  // The sampled grid point nearest (x, y); false outside the classified part of the image (the
  // rounding is floor(· + ½), which is all that matters inside it).
  const double inv_s = 1.0 / s;
  const auto grid = [&](double x, double y, int& gx, int& gy) {
    const double fx = x * inv_s + 0.5, fy = (y - first) * inv_s + 0.5;
    if (fx < 0.0 || fy < 0.0) return false;
    gx = static_cast<int>(fx) * s;
    gy = first + static_cast<int>(fy) * s;
    return gx < classes.width() && gy < classes.height();
  };
  int cx = 0, cy = 0;
  if (!grid(centre.u, centre.v, cx, cy) || !non_field(classes, cx, cy)) return {centre, 0.0};
  const double reach = params_.max_extent * radius;
  // Half a sample (diagonal rays then see the outline more finely), but no finer than a
  // sixteenth of the radius: a near ball's outline needs no more points along its rays than a far
  // one's, and at 40 px its 16 rays would otherwise read 2000 samples.
  const double step = std::max(0.5 * s, radius / 16.0);
  std::size_t n = 0;
  for (const auto& d : kRays) {
    bool field_before = false;
    for (double t = step; t <= reach; t += step) {
      int gx = 0, gy = 0;
      ++refine_samples_;
      if (!grid(centre.u + t * d[0], centre.v + t * d[1], gx, gy)) break;  // the border: no outline
      const bool field = !non_field(classes, gx, gy);
      if (field && field_before) {  // two field samples in a row: the outline lies before them
        outline_[n] = {centre.u + (t - 1.5 * step) * d[0], centre.v + (t - 1.5 * step) * d[1]};
        ++n;
        break;
      }
      field_before = field;
    }
  }
  if (static_cast<int>(n) < params_.min_outline_points) return {centre, 0.0};
  const IndexedPoints pts{outline_, std::span<const int>(kFirstSixteen.data(), n)};
  const auto fit = fit_circle_geometric(pts, {{centre.u, centre.v}, radius}, true, 5);
  if (!fit || hal::portable_hypot(fit->centre.x - centre.u, fit->centre.y - centre.v) > radius) return {centre, 0.0};
  // Roundness: the share of rays with an outline, less for outline points off the circle (RMS
  // against a quarter of the radius: a sample step of noise costs little, a square foot more).
  const double rms = circle_rms(*fit, pts);
  const double fit_quality = std::max(0.0, 1.0 - rms / (0.25 * radius + s));
  return {{fit->centre.x, fit->centre.y}, static_cast<double>(n) / static_cast<double>(kRays.size()) * fit_quality};
}

namespace {

// (bright − dark) / (bright + 1) over a grid of samples inside 0.7 × radius: the second brightest
// and second darkest, so one noisy pixel does not decide it.
double inner_contrast(const hal::FrameView& frame, const hal::Pixel& centre, double radius) noexcept {
  std::array<int, 2> hi{-1, -1};
  std::array<int, 2> lo{256, 256};
  int n = 0;
  constexpr int kGrid = kContrastGrid;
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      const double dx = (2.0 * (i + 0.5) / kGrid - 1.0) * 0.7 * radius;
      const double dy = (2.0 * (j + 0.5) / kGrid - 1.0) * 0.7 * radius;
      if (dx * dx + dy * dy > 0.49 * radius * radius) continue;
      const int x = static_cast<int>(centre.u + dx);
      const int y = static_cast<int>(centre.v + dy);
      if (x < 0 || y < 0 || x >= frame.width || y >= frame.height) continue;
      const int l = luma_at(frame, x, y);
      if (l > hi[0]) {
        hi[1] = hi[0];
        hi[0] = l;
      } else if (l > hi[1]) {
        hi[1] = l;
      }
      if (l < lo[0]) {
        lo[1] = lo[0];
        lo[0] = l;
      } else if (l < lo[1]) {
        lo[1] = l;
      }
      ++n;
    }
  }
  if (n < 4) return 0.0;
  return std::max(0, hi[1] - lo[1]) / static_cast<double>(hi[1] + 1);
}

}  // namespace

void BwBallDetector::add(const Candidate& c) noexcept {
  for (std::size_t i = 0; i < count_; ++i) {
    Candidate& o = cands_[i];
    const double reach = params_.merge_radii * std::max(o.radius, c.radius);
    if (std::abs(o.centre.u - c.centre.u) <= reach && std::abs(o.centre.v - c.centre.v) <= reach) {
      if (c.rank() > o.rank()) o = c;
      return;
    }
  }
  if (count_ < cands_.size()) {
    cands_[count_++] = c;
    return;
  }
  // Full: replace the worst if this one is better.
  auto worst = std::min_element(cands_.begin(), cands_.end(),
                                [](const Candidate& a, const Candidate& b) { return a.rank() < b.rank(); });
  if (worst->rank() < c.rank()) *worst = c;
}

void BwBallDetector::detect(const ClassImage& classes, const hal::FrameView& frame, const hal::CameraIntrinsics& k,
                            const hal::CameraPose& pose, int stride, HogClassifier* classifier, int max_verified,
                            const Deadline& deadline, BallList& out) noexcept {
  const bool verifying = classifier != nullptr && max_verified > 0;
  propose(classes, frame, k, pose, stride, verifying, out);
  if (verifying) verify(frame, k, pose, *classifier, max_verified, max_verified, deadline, out);
}

BallDetection BwBallDetector::detection(const Candidate& c, const BallPlane& plane) noexcept {
  BallDetection b;
  b.seen = true;
  b.centre = c.centre;
  b.radius_px = c.radius;
  b.pixels = static_cast<int>(3.14159265358979 * c.radius * c.radius);
  hal::RobotPoint g{};
  if (plane.ground(c.centre, g)) {
    b.ground = g;
    b.ground_valid = true;
    b.distance_m = hal::portable_hypot(g.x, g.y);
    b.bearing_rad = std::atan2(g.y, g.x);
  }
  return b;
}

void BwBallDetector::propose(const ClassImage& classes, const hal::FrameView& frame, const hal::CameraIntrinsics& k,
                             const hal::CameraPose& pose, int stride, bool to_be_verified, BallList& out) noexcept {
  out = BallList{};
  count_ = 0;
  failed_count_ = 0;
  refine_samples_ = 0;
  const int s = classes.step();
  const int col_stride = std::max(s, (std::max(stride, 1) + s - 1) / s * s);
  const int first = classes.first_row();
  const int h = classes.height();
  const BallPlane plane(k, pose, params_.radius_m);
  const auto radius_at = [&](const hal::Pixel& px) {
    refine_samples_ += kRadiusSamples;
    return plane.radius_px(px);
  };
  const auto consider = [&](int x, double cy_guess) {
    const double r = radius_at({x + 0.5 * s, cy_guess});
    if (r < params_.min_radius_px) return;
    const double d = 2.0 * r;
    const int reach = static_cast<int>(std::ceil(params_.max_extent * d)) + s;
    int top = 0, bottom = 0, left = 0, right = 0;
    const int yc = std::clamp(first + (static_cast<int>(cy_guess) - first) / s * s, first, h - 1);
    if (!non_field(classes, x, yc)) return;
    refine_samples_ += horizontal_extent(classes, x, yc, reach, left, right);
    const double width = right - left + s;
    const int xc = left + (right - left) / 2 / s * s;
    double cx = xc + 0.5 * s;
    if (width > params_.max_extent * d) cx = x + 0.5 * s;  // wider than a ball (a line): keep the column
    const int xs = width > params_.max_extent * d ? x : xc;
    refine_samples_ += vertical_extent(classes, xs, yc, reach, top, bottom);
    const double height = bottom - top + s;
    double cy = 0.5 * (top + bottom + s);
    if (height > params_.max_extent * d) cy = cy_guess;
    // A ball cut by the image's edge: its centre lies a radius inside the part seen (the middle of
    // that part lies up to half a radius off).
    if (width < d) {
      if (left < s && right + s < classes.width()) cx = right + s - r;
      if (right + s >= classes.width() && left >= s) cx = left + r;
    }
    if (height < d && bottom + s >= h) cy = top + r;
    double r2 = radius_at({cx, cy});
    if (r2 < params_.min_radius_px) return;
    // The neighbouring columns of a blob already outlined give the same candidate: not refined again.
    const auto within = [&](const hal::Pixel& o, double half_side) { return std::abs(o.u - cx) <= half_side && std::abs(o.v - cy) <= half_side; };
    for (std::size_t i = 0; i < count_; ++i) {
      if (cands_[i].roundness > 0.0 && within(cands_[i].centre, 0.5 * r2)) return;
    }
    // Only a blob with black on white inside is worth its outline (the costly part), and only once:
    // where an outline failed, its neighbours' would too. (On a robot's white body with its dark
    // joints every column's run passed the contrast test and walked the 16 rays again: 40k samples,
    // twice the whole grid's, in a frame of the SPL run.)
    const double raw_contrast = inner_contrast(frame, {cx, cy}, r2);
    refine_samples_ += kContrastSamples;
    const bool failed_here = std::any_of(failed_outlines_.begin(), failed_outlines_.begin() + static_cast<std::ptrdiff_t>(failed_count_),
                                         [&](const hal::Pixel& o) { return within(o, r2); });
    const bool outlining = raw_contrast >= params_.min_contrast && !failed_here;
    const Outline outline = outlining ? fit_outline(classes, {cx, cy}, r2) : Outline{{cx, cy}, 0.0};
    if (outlining && outline.roundness <= 0.0 && failed_count_ < failed_outlines_.size()) {
      failed_outlines_[failed_count_++] = {cx, cy};
    }
    const double r3 = radius_at(outline.centre);
    double contrast = raw_contrast;
    if (r3 >= params_.min_radius_px && (outline.centre.u != cx || outline.centre.v != cy)) {
      cx = outline.centre.u;
      cy = outline.centre.v;
      r2 = r3;
      contrast = inner_contrast(frame, {cx, cy}, r2);  // the outline moved the ball: look again
      refine_samples_ += kContrastSamples;
    }
    const double e = match(std::min(width, params_.max_extent * 2.0 * r2), 2.0 * r2) *
                     match(std::min(height, params_.max_extent * 2.0 * r2), 2.0 * r2);
    add({{cx, cy}, r2, e, outline.roundness, contrast});
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
      const double r = radius_at({x + 0.5 * s, mid});
      if (r >= params_.min_radius_px) {
        const double d = 2.0 * r;
        if (len >= params_.min_extent * d && len <= params_.max_extent * d) {
          consider(x, mid);
        } else if (y >= h && len >= params_.min_cut_extent * d && len < params_.min_extent * d) {
          consider(x, run_start + r);  // cut by the bottom edge: the ball's top is seen
        } else if (len > params_.max_extent * d && y < h) {
          // Too long: a ball may stand in front of whatever continues above it.
          const double rb = radius_at({x + 0.5 * s, y - r});
          if (rb >= params_.min_radius_px) consider(x, y - rb);
        }
      }
      run_start = -1;
    }
  }
  out.candidates = static_cast<int>(count_);
  out.refine_samples = static_cast<int>(refine_samples_);
  // Rank (BallCandidate::rank); insertion sort (stable, and std::stable_sort may allocate a buffer).
  for (std::size_t i = 1; i < count_; ++i) {
    const Candidate c = cands_[i];
    std::size_t j = i;
    for (; j > 0 && cands_[j - 1].rank() < c.rank(); --j) cands_[j] = cands_[j - 1];
    cands_[j] = c;
  }

  if (!to_be_verified && count_ > 0) {
    BallDetection& b = out.balls[0];
    b = detection(cands_[0], plane);
    b.confidence = 0.3 * std::min(1.0, cands_[0].rank());
    out.count = 1;
  }
}

void BwBallDetector::verify(const hal::FrameView& frame, const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
                            HogClassifier& classifier, int max_verified, int windows_allowed, const Deadline& deadline,
                            BallList& out) noexcept {
  const double threshold = classifier.model().threshold();
  const BallPlane plane(k, pose, params_.radius_m);
  const std::size_t n = std::min(count_, static_cast<std::size_t>(std::max(max_verified, 0)));
  for (std::size_t i = 0; i < n; ++i) {
    if (deadline.expired() || out.classified >= windows_allowed) {
      out.classifications_cut = static_cast<int>(n - i);
      break;
    }
    const Candidate& c = cands_[i];
    const WindowPlacement w = ball_window(params_, classifier.model().params(), c.centre, c.radius);
    const double score = classifier.score_window(frame, w.left, w.top, w.scale);
    ++out.classified;
    if (score < threshold) continue;
    BallDetection b = detection(c, plane);
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
