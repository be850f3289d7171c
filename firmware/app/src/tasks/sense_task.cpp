#include "ringlet/firmware/tasks/sense_task.hpp"

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

}  // namespace

std::unique_ptr<executive::Task> SenseTask::make(TaskServices& services) {
  return std::make_unique<SenseTask>(services.robot.sensors(), services.board);
}

void SenseTask::run(const executive::TaskContext& ctx) noexcept {
  const bool ok = sensors_.read(frame_);
  if (!ok && sensors_.exhausted()) ctx.request_stop();  // a replayed log has ended
  board_.post(wb::Pose{frame_.pose.pose.x, frame_.pose.pose.y, frame_.pose.pose.theta, ok && frame_.pose.valid});
  board_.post(summarize(frame_.laser));
  board_.post(wb::HeadPosture{frame_.stamp.count(), frame_.head.yaw, frame_.head.pitch, frame_.body.tilt.pitch,
                              frame_.body.tilt.roll, frame_.body.valid});
  board_.post(wb::BodyState{frame_.stamp.count(), frame_.odometry.distance, frame_.odometry.velocity,
                            frame_.odometry.curvature, frame_.collided, frame_.power.battery_volts});
}

}  // namespace ringlet::firmware
