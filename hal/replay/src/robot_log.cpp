#include "ringlet/hal/robot_log.hpp"

#include <algorithm>
#include <bit>
#include <cassert>

#include "le_bytes.hpp"

namespace ringlet::hal {
namespace {

void put_record_header(LeWriter& w, RecordKind kind, std::size_t payload) {
  w.u8(static_cast<std::uint8_t>(kind));
  w.u32(static_cast<std::uint32_t>(payload));
}

}  // namespace

const char* to_string(RecordKind kind) noexcept {
  switch (kind) {
    case RecordKind::kSensor: return "sensor";
    case RecordKind::kBall: return "ball";
    case RecordKind::kCamera: return "camera";
    case RecordKind::kGap: return "gap";
    case RecordKind::kEnd: return "end";
  }
  return "unknown";
}

void append_header(std::vector<std::uint8_t>& out, const LogHeader& header) {
  LeWriter w{out};
  w.bytes(reinterpret_cast<const std::uint8_t*>(kRobotLogMagic.data()), kRobotLogMagic.size());
  w.u32(header.version);
  w.i64(header.period.count());
  const std::size_t note = std::min(header.note.size(), kMaxLogNoteBytes);
  w.u32(static_cast<std::uint32_t>(note));
  w.bytes(reinterpret_cast<const std::uint8_t*>(header.note.data()), note);
}

void append_record(std::vector<std::uint8_t>& out, const SensorRecord& r) {
  LeWriter w{out};
  const SensorFrame& f = r.frame;
  const std::size_t beams = std::min<std::size_t>(f.laser.beam_count, LaserScan::kMaxBeams);
  put_record_header(w, RecordKind::kSensor, kSensorFixedBytes + kBytesPerBeam * beams);
  const std::size_t start = out.size();
  w.u64(r.index);
  w.boolean(r.ok);
  w.i64(f.stamp.count());
  w.i64(f.pose.stamp.count());
  w.f64(f.pose.pose.x);
  w.f64(f.pose.pose.y);
  w.f64(f.pose.pose.theta);
  w.boolean(f.pose.valid);
  w.i64(f.odometry.stamp.count());
  w.f64(f.odometry.distance);
  w.f64(f.odometry.velocity);
  w.f64(f.odometry.curvature);
  w.f64(f.head.yaw);
  w.f64(f.head.pitch);
  w.i64(f.body.stamp.count());
  w.f64(f.body.tilt.pitch);
  w.f64(f.body.tilt.roll);
  w.boolean(f.body.valid);
  w.f64(f.power.battery_volts);
  w.f64(f.power.bus_volts);
  w.i64(f.laser.stamp.count());
  w.u16(static_cast<std::uint16_t>(beams));
  w.f64(f.laser.angle_min);
  w.f64(f.laser.angle_increment);
  w.f64(f.laser.max_range);
  w.boolean(f.collided);
  assert(out.size() - start == kSensorFixedBytes);
  for (std::size_t i = 0; i < beams; ++i) {
    w.u32(std::bit_cast<std::uint32_t>(f.laser.range[i]));
    w.boolean(f.laser.valid[i]);
  }
  (void)start;
}

void append_record(std::vector<std::uint8_t>& out, const BallRecord& r) {
  LeWriter w{out};
  put_record_header(w, RecordKind::kBall, kBallPayloadBytes);
  w.u64(r.reads);
  w.boolean(r.ok);
  w.i64(r.sighting.stamp.count());
  w.boolean(r.sighting.seen);
  w.f64(r.sighting.at.x);
  w.f64(r.sighting.at.y);
}

void append_record(std::vector<std::uint8_t>& out, const CameraRecord& r, const std::uint8_t* pixels) {
  LeWriter w{out};
  put_record_header(w, RecordKind::kCamera, kCameraFixedBytes + r.pixel_bytes());
  w.u64(r.reads);
  w.i64(r.capture_time.count());
  w.u64(r.sequence);
  w.u8(static_cast<std::uint8_t>(r.format));
  w.u32(r.width);
  w.u32(r.height);
  w.u32(r.stride);
  w.bytes(pixels, r.pixel_bytes());
}

void append_record(std::vector<std::uint8_t>& out, const GapRecord& r) {
  LeWriter w{out};
  put_record_header(w, RecordKind::kGap, kGapPayloadBytes);
  w.u64(r.reads);
  w.u32(r.dropped.sensor);
  w.u32(r.dropped.ball);
  w.u32(r.dropped.camera);
}

void append_record(std::vector<std::uint8_t>& out, const EndRecord& r) {
  LeWriter w{out};
  put_record_header(w, RecordKind::kEnd, kEndPayloadBytes);
  w.u64(r.sensor_reads);
  w.u64(r.dropped);
}

}  // namespace ringlet::hal
