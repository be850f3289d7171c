#include "ringlet/vision/messages.hpp"

#include <algorithm>

namespace ringlet::vision {

wb::FieldLines to_field_lines(const VisionResult& r) noexcept {
  wb::FieldLines m{};
  m.sequence = r.sequence;
  m.capture_time_ns = r.capture_time.count();
  const std::size_t n = std::min(r.line_count, m.length.size());
  m.count = static_cast<std::uint8_t>(n);
  for (std::size_t i = 0; i < n; ++i) {
    const FieldLine& l = r.lines[i];
    m.image_u0[i] = l.image_start.u;
    m.image_v0[i] = l.image_start.v;
    m.image_u1[i] = l.image_end.u;
    m.image_v1[i] = l.image_end.v;
    m.ground_x0[i] = l.ground_start.x;
    m.ground_y0[i] = l.ground_start.y;
    m.ground_x1[i] = l.ground_end.x;
    m.ground_y1[i] = l.ground_end.y;
    m.length[i] = l.length_m;
    m.inliers[i] = static_cast<std::uint16_t>(l.inliers);
  }
  m.circle_seen = r.circle.seen;
  m.circle_x = r.circle.centre.x;
  m.circle_y = r.circle.centre.y;
  m.circle_radius = r.circle.radius_m;
  const std::size_t marks = std::min(r.marks.count, m.mark_x.size());
  m.mark_count = static_cast<std::uint8_t>(marks);
  for (std::size_t i = 0; i < marks; ++i) {
    const FieldMark& f = r.marks.marks[i];
    m.mark_x[i] = f.centre.x;
    m.mark_y[i] = f.centre.y;
    m.mark_orientation[i] = f.orientation_rad;
    m.mark_confidence[i] = f.confidence;
  }
  return m;
}

wb::BallBelief to_ball_belief(const VisionResult& r) noexcept {
  wb::BallBelief b{};
  b.visible = r.ball.seen && r.ball.ground_valid;
  if (b.visible) {
    b.x = r.ball.ground.x;
    b.y = r.ball.ground.y;
    b.confidence = r.ball.confidence;
  }
  b.simulated = false;
  return b;
}

wb::RobotDetections to_robot_detections(const VisionResult& r) noexcept {
  wb::RobotDetections m{};
  m.sequence = r.sequence;
  m.capture_time_ns = r.capture_time.count();
  const std::size_t n = std::min(r.robots.count, m.foot_x.size());
  m.count = static_cast<std::uint8_t>(n);
  for (std::size_t i = 0; i < n; ++i) {
    const RobotDetection& d = r.robots.robots[i];
    m.foot_x[i] = d.ground.x;
    m.foot_y[i] = d.ground.y;
    m.distance[i] = d.distance_m;
    m.bearing[i] = d.bearing_rad;
    m.verified[i] = d.verified ? 1 : 0;
    m.confidence[i] = d.confidence;
  }
  return m;
}

}  // namespace ringlet::vision
