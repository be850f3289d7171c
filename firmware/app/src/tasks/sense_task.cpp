#include "ringlet/firmware/tasks/sense_task.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace ringlet::firmware {
namespace {

// The nearest valid return of a scan, bearing in the robot frame (left positive, like
// hal::RobotPoint; the laser's own angles are positive to the right).
wb::LaserSummary summarize(const hal::LaserScan& scan) noexcept {
  wb::LaserSummary s{};
  s.nearest_range = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < scan.beam_count; ++i) {
    if (!scan.valid[i]) continue;
    ++s.valid_beams;
    const double range = static_cast<double>(scan.range[i]);
    if (range < s.nearest_range) {
      s.nearest_range = range;
      s.nearest_bearing = -scan.beam_angle(i);
    }
  }
  if (s.valid_beams == 0) s.nearest_range = scan.max_range;  // nothing within range
  return s;
}

// The scan in whiteboard form: millimetres, 0 for no return (ranges beyond 65.534 m saturate).
void to_message(const hal::LaserScan& scan, std::int64_t stamp_ns, wb::LaserScan& m) noexcept {
  m.stamp_ns = stamp_ns;
  m.beam_count = static_cast<std::uint16_t>(std::min<std::size_t>(scan.beam_count, m.range_mm.size()));
  m.angle_min = scan.angle_min;
  m.angle_increment = scan.angle_increment;
  m.max_range = scan.max_range;
  for (std::size_t i = 0; i < m.range_mm.size(); ++i) {
    const double r = i < m.beam_count && scan.valid[i] ? static_cast<double>(scan.range[i]) : 0.0;
    m.range_mm[i] = r > 0.0 && std::isfinite(r) ? static_cast<std::uint16_t>(std::clamp(std::lround(r * 1000.0), 1L, 65534L)) : 0;
  }
}

wb::BoardHealth to_message(const hal::BoardHealth& h) noexcept {
  return {h.frames_received, h.frames_sent,    h.malformed,      h.unknown_id,      h.stale_readings,
          h.heartbeat_losses, h.bus_off,       h.error_passive,  h.tx_full,         h.socket_failures,
          h.reconnects,       h.refused_commands, h.board_faults, h.last_fault,     h.incomplete_scans,
          static_cast<std::uint8_t>(h.bus), h.board_state, h.board_alive};
}

}  // namespace

std::unique_ptr<executive::Task> SenseTask::make(TaskServices& services) {
  return std::make_unique<SenseTask>(services.robot.sensors(), services.board, services.robot.board_health());
}

std::unique_ptr<executive::Task> SenseNoGpsTask::make(TaskServices& services) {
  return std::make_unique<SenseNoGpsTask>(services.robot.sensors(), services.board, services.robot.board_health(),
                                          false);
}

void SenseTask::run(const executive::TaskContext& ctx) noexcept {
  const bool ok = sensors_.read(frame_);
  if (!ok && sensors_.exhausted()) ctx.request_stop();  // a replayed log has ended
  if (posts_gps_) board_.post(wb::Pose{frame_.pose.pose.x, frame_.pose.pose.y, frame_.pose.pose.theta, ok && frame_.pose.valid});
  board_.post(summarize(frame_.laser));
  to_message(frame_.laser, frame_.stamp.count(), scan_);
  board_.post(scan_);
  board_.post(wb::HeadPosture{frame_.stamp.count(), frame_.head.yaw, frame_.head.pitch, frame_.body.tilt.pitch,
                              frame_.body.tilt.roll, frame_.body.valid});
  board_.post(wb::BodyState{frame_.stamp.count(), frame_.odometry.distance, frame_.odometry.velocity,
                            frame_.odometry.curvature, frame_.collided, frame_.power.battery_volts});
  if (health_ != nullptr && ctx.first_frame_of_each(std::chrono::seconds{1})) board_.post(to_message(*health_));
}

}  // namespace ringlet::firmware
