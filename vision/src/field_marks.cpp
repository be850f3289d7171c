// The painted crosses (field_marks.hpp): leftover candidates → lone clusters → a cross in the picture.
#include "ringlet/vision/field_marks.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ringlet/hal/portable_math.hpp"

namespace ringlet::vision {
namespace {

constexpr int kOrientations = 18;  // 0°, 5°, ... 85°: a cross repeats every 90°
// (cos, sin) of 0°, 5°, ... 85°, as literals: std::cos may round differently on x86-64 and aarch64,
// and what the cross's samples read must be the same on both.
constexpr std::array<std::array<double, 2>, kOrientations> kDirections{{
    {1.0, 0.0},
    {0.9961946980917455, 0.08715574274765817},
    {0.984807753012208, 0.17364817766693033},
    {0.9659258262890683, 0.25881904510252074},
    {0.9396926207859084, 0.3420201433256687},
    {0.9063077870366499, 0.42261826174069944},
    {0.8660254037844387, 0.49999999999999994},
    {0.8191520442889918, 0.573576436351046},
    {0.766044443118978, 0.6427876096865393},
    {0.7071067811865476, 0.7071067811865475},
    {0.6427876096865394, 0.766044443118978},
    {0.5735764363510462, 0.8191520442889918},
    {0.5000000000000001, 0.8660254037844386},
    {0.42261826174069944, 0.9063077870366499},
    {0.3420201433256688, 0.9396926207859083},
    {0.25881904510252074, 0.9659258262890683},
    {0.17364817766693041, 0.984807753012208},
    {0.08715574274765814, 0.9961946980917455},
}};
constexpr int kRingSamples = 12;  // every 30°
// The most tests judge() counts: the ring, two circles of 72 samples, the cross's 13 points.
constexpr std::int64_t kJudgeTests = kRingSamples + 2 * 72 + 13;

struct Direction {
  double c;
  double s;
};
// (cos, sin) of m × 5°, any m ≥ 0: kDirections turned by multiples of 90°.
Direction direction(int m) noexcept {
  const auto& d = kDirections[static_cast<std::size_t>(m % kOrientations)];
  switch (m / kOrientations % 4) {
    case 0: return {d[0], d[1]};
    case 1: return {-d[1], d[0]};
    case 2: return {-d[0], -d[1]};
    default: return {d[1], -d[0]};
  }
}

double distance_to_segment(const hal::RobotPoint& p, const hal::RobotPoint& a, const hal::RobotPoint& b) noexcept {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double l2 = dx * dx + dy * dy;
  const double t = l2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
  const double ex = p.x - (a.x + t * dx), ey = p.y - (a.y + t * dy);
  return std::sqrt(ex * ex + ey * ey);
}

double dist2(const hal::RobotPoint& a, const hal::RobotPoint& b) noexcept {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return dx * dx + dy * dy;
}

}  // namespace

FieldMarkFinder::FieldMarkFinder(const FieldMarkParams& params, std::size_t capacity)
    : params_(params), limit_(std::min(capacity, static_cast<std::size_t>(std::max(params.max_points, 0)))) {
  left_.reserve(limit_);
  taken_.reserve(limit_);
}

std::array<std::array<hal::RobotPoint, 2>, 2> FieldMarkFinder::bars(const FieldMark& mark, double bar_length_m) noexcept {
  const double h = bar_length_m / 2.0;
  const double ux = std::cos(mark.orientation_rad) * h, uy = std::sin(mark.orientation_rad) * h;
  const hal::RobotPoint c = mark.centre;
  return {{{{{c.x - ux, c.y - uy}, {c.x + ux, c.y + uy}}}, {{{c.x + uy, c.y - ux}, {c.x - uy, c.y + ux}}}}};
}

double FieldMarkFinder::cluster_radius(const hal::RobotPoint& p, const hal::CameraIntrinsics& k,
                                       const hal::CameraPose& pose) const noexcept {
  // One image row moves a ground point along its viewing ray by (r² + h²) / (h · fy).
  const double r2 = dist2(p, {pose.position.x, pose.position.y});
  const double h = std::max(pose.position.z, 1e-3);
  return params_.cluster_radius_m + params_.range_rows * (r2 + h * h) / (h * std::max(k.fy, 1.0));
}

bool FieldMarkFinder::judge(const hal::RobotPoint& c, const ClassImage& classes, const hal::CameraIntrinsics& k,
                            const hal::CameraPose& pose, FieldMark& mark, std::int64_t& tests) const noexcept {
  const auto class_at = [&](double x, double y) {
    ++tests;
    const auto px = hal::project(k, pose, {x, y, 0.0});
    return px ? classes.class_near(px->u, px->v) : ColourClass::kOther;
  };
  if (!hal::project(k, pose, {c.x, c.y, 0.0})) return false;
  // The ring: carpet all round (inside the picture).
  int judged = 0, field = 0;
  constexpr int n = kRingSamples;
  for (int i = 0; i < n; ++i) {
    const Direction d = direction(6 * i);
    const double x = c.x + params_.clear_radius_m * d.c, y = c.y + params_.clear_radius_m * d.s;
    const auto px = hal::project(k, pose, {x, y, 0.0});
    ++tests;
    if (!px || px->u < 0.0 || px->u >= classes.width() || px->v < classes.first_row() || px->v >= classes.height()) continue;
    ++judged;
    field += classes.class_near(px->u, px->v) == ColourClass::kField ? 1 : 0;
  }
  if (2 * judged < n || static_cast<double>(field) < params_.min_ring_field * static_cast<double>(judged)) return false;
  // The orientation: where around the centre the paint lies. Samples on two small circles (every
  // 5°); the arms put the painted ones around θ, θ + 90°, ... so the mean of their angles times
  // four gives 4θ.
  double c4 = 0.0, s4 = 0.0;
  int painted = 0;
  for (const double radius : {0.3 * params_.bar_length_m, 0.45 * params_.bar_length_m}) {
    for (int m = 0; m < 72; ++m) {
      const Direction d = direction(m);
      if (class_at(c.x + radius * d.c, c.y + radius * d.s) != ColourClass::kLine) continue;
      const Direction d4 = direction(4 * m);
      c4 += d4.c;
      s4 += d4.s;
      ++painted;
    }
  }
  const double r4 = hal::portable_hypot(c4, s4);
  if (painted == 0 || r4 < 1e-9) return false;
  // cos θ and sin θ from cos 4θ and sin 4θ by two half angles (square roots round the same on
  // every host; std::cos need not), θ in (−45°, 45°].
  const double cos4 = c4 / r4;
  const double cos2 = std::sqrt(std::max(0.0, (1.0 + cos4) / 2.0));
  const double sin2 = std::copysign(std::sqrt(std::max(0.0, (1.0 - cos4) / 2.0)), s4);
  const double ux = std::sqrt(std::max(0.0, (1.0 + cos2) / 2.0));
  const double uy = std::copysign(std::sqrt(std::max(0.0, (1.0 - cos2) / 2.0)), sin2);
  const double theta = hal::portable_atan2(uy, ux);
  mark.orientation_rad = theta < 0.0 ? theta + std::numbers::pi / 2.0 : theta;
  // The cross at that orientation: paint on both bars (the centre and two points out each arm),
  // carpet in the four corners between the arms.
  const double arm = params_.bar_length_m * 0.4;
  const double corner = (params_.bar_length_m + params_.bar_width_m) / 4.0;  // between bar edge and square edge
  int score = class_at(c.x, c.y) == ColourClass::kLine ? 1 : 0;
  for (const double t : {-arm, -arm / 2.0, arm / 2.0, arm}) {
    score += class_at(c.x + t * ux, c.y + t * uy) == ColourClass::kLine ? 1 : 0;
    score += class_at(c.x - t * uy, c.y + t * ux) == ColourClass::kLine ? 1 : 0;
  }
  for (const double su : {-corner, corner}) {
    for (const double sv : {-corner, corner}) {
      score += class_at(c.x + su * ux - sv * uy, c.y + su * uy + sv * ux) == ColourClass::kField ? 1 : 0;
    }
  }
  mark.confidence = static_cast<double>(score) / 13.0;
  return mark.confidence >= params_.min_confidence;
}

void FieldMarkFinder::find(std::span<const CandidatePoint> candidates, std::span<const FieldLine> lines,
                           const CentreCircle& circle, std::span<const BallDetection> balls, const ClassImage& classes,
                           const hal::CameraIntrinsics& k, const hal::CameraPose& pose, const Deadline& deadline,
                           FieldMarkList& out, std::int64_t max_tests) noexcept {
  out = FieldMarkList{};
  if (!params_.enabled) return;
  // 1. What the lines, the circle and the balls leave over, near enough.
  left_.clear();
  const double max_range2 = params_.max_range_m * params_.max_range_m;
  const auto line_tests = static_cast<std::int64_t>(lines.size());
  for (const CandidatePoint& cp : candidates) {
    if (left_.size() == limit_) break;
    if (out.tests + line_tests > max_tests) {  // a candidate tests at most every line
      out.stopped_early = true;
      return;
    }
    const hal::RobotPoint& q = cp.ground;
    if (q.x * q.x + q.y * q.y > max_range2) continue;
    bool claimed = false;
    for (const FieldLine& l : lines) {
      ++out.tests;
      if (distance_to_segment(q, l.ground_start, l.ground_end) <= params_.line_clearance_m) {
        claimed = true;
        break;
      }
    }
    if (claimed) continue;
    if (circle.seen && std::abs(hal::portable_hypot(q.x - circle.centre.x, q.y - circle.centre.y) - circle.radius_m) <=
                           params_.circle_band_m) {
      continue;
    }
    for (const BallDetection& b : balls) {
      claimed = claimed || (b.ground_valid && dist2(q, b.ground) <= params_.ball_clearance_m * params_.ball_clearance_m);
    }
    if (!claimed) left_.push_back(q);
  }
  out.leftovers = static_cast<int>(left_.size());
  taken_.assign(left_.size(), 0);

  // 2. Lone clusters, in candidate order (the scan's, so deterministic), each judged in the picture.
  for (std::size_t i = 0; i < left_.size() && out.count < kMaxFieldMarks; ++i) {
    if (taken_[i] != 0) continue;
    if (deadline.expired() ||
        out.tests + 3 * static_cast<std::int64_t>(left_.size()) + kJudgeTests > max_tests) {
      out.stopped_early = true;
      break;
    }
    const double r = cluster_radius(left_[i], k, pose);
    const double clear = r + params_.clear_radius_m - params_.cluster_radius_m;
    // The seed may lie at the end of an arm: gather out to the cross's whole span (2r) first, then
    // twice around the centroid (r), counting what lies between the cross and the clear ring.
    hal::RobotPoint centre = left_[i];
    double reach = 2.0 * r;
    int members = 0;
    int around = 0;
    for (int pass = 0; pass < 3; ++pass) {
      hal::RobotPoint sum{};
      members = 0;
      around = 0;
      for (std::size_t j = 0; j < left_.size(); ++j) {
        ++out.tests;
        const double d2 = dist2(centre, left_[j]);
        if (d2 <= reach * reach) {
          sum.x += left_[j].x;
          sum.y += left_[j].y;
          ++members;
        } else if (d2 > 2.25 * r * r && d2 <= clear * clear) {  // a margin for a centroid a little off
          ++around;
        }
      }
      if (members < params_.min_points) break;
      centre = {sum.x / members, sum.y / members};
      reach = r;
    }
    if (members < params_.min_points) continue;
    for (std::size_t j = 0; j < left_.size(); ++j) {
      if (dist2(centre, left_[j]) <= 4.0 * r * r) taken_[j] = 1;  // the whole span: one cross, one cluster
    }
    if (around > params_.max_ring_points) continue;
    ++out.clusters;
    FieldMark mark;
    if (!judge(centre, classes, k, pose, mark, out.tests)) {
      ++out.rejected;
      continue;
    }
    mark.centre = centre;
    mark.points = members;
    mark.distance_m = hal::portable_hypot(centre.x, centre.y);
    mark.bearing_rad = hal::portable_atan2(centre.y, centre.x);
    out.marks[out.count++] = mark;
  }
}

}  // namespace ringlet::vision
