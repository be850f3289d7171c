#include "ringlet/sim_hal/software_board.hpp"

#include <algorithm>
#include <cmath>

namespace ringlet::sim_hal {

using namespace hal::can;

SoftwareBoard::SoftwareBoard(SimRobot& robot, CanSocket socket, const SoftwareBoardSettings& settings)
    : robot_(robot), socket_(std::move(socket)), settings_(settings) {}

void SoftwareBoard::send(std::uint32_t id, const Values& v) noexcept {
  RawFrame raw;
  if (!encode(*find_frame(id), v, raw).ok()) return;  // a simulated value outside the protocol: not sent
  switch (socket_.send(raw)) {
    case SendStatus::kSent: ++counts_.frames_sent; break;
    case SendStatus::kQueueFull: ++counts_.tx_full; break;
    case SendStatus::kFailed: break;
  }
}

void SoftwareBoard::take_commands(hal::Nanos now) noexcept {
  for (int i = 0; i < 1024; ++i) {
    RawFrame raw;
    const ReceiveStatus st = socket_.receive(raw);
    if (st == ReceiveStatus::kEmpty || st == ReceiveStatus::kFailed) return;
    if (st != ReceiveStatus::kFrame) continue;
    const FrameSpec* spec = nullptr;
    Values v;
    if (!decode(raw, spec, v).ok()) {
      ++counts_.refused;
      continue;
    }
    if (spec->id == kDriveId) {
      ++counts_.commands;
      last_command_ = now;
      drive_counter_ = static_cast<std::uint8_t>(v[2]);
      const bool enable = v[3] > 0.5;
      command_.drive = enable ? hal::DriveCommand{v[0], v[1]} : hal::DriveCommand{};
      if (enable) commanded_ = true;
    } else if (spec->id == kHeadCommandId) {
      command_.head = {v[0], v[1]};
    } else if (spec->id == kSafeStateId) {
      state_ = BoardState::kSafe;
    }
  }
}

// A scan goes out over the period it covers, not in one burst: its header at once, then its range
// frames in equal slices over the next laser_every steps. No controller activation then drains a
// whole scan (62 frames for 181 beams), and on a real bus the other sensors' frames are not held
// up behind a burst of eight milliseconds at 1 Mbit/s.
void SoftwareBoard::start_laser(const hal::LaserScan& scan) noexcept {
  scan_ = scan;
  ++scan_counter_;
  const double max_range = std::clamp(scan.max_range, 0.1, 25.5);
  send(kLaserHeaderId, values_of({static_cast<double>(scan_counter_), static_cast<double>(scan.beam_count), scan.angle_min,
                                  scan.angle_increment, max_range}));
  scan_chunks_ = (scan.beam_count + kBeamsPerChunk - 1) / kBeamsPerChunk;
  next_chunk_ = 0;
}

void SoftwareBoard::send_laser_slice() noexcept {
  const auto steps = static_cast<std::size_t>(std::max(settings_.laser_every, 1));
  const std::size_t per_step = (scan_chunks_ + steps - 1) / steps;
  for (std::size_t n = 0; n < per_step && next_chunk_ < scan_chunks_; ++n, ++next_chunk_) {
    const std::size_t c = next_chunk_;
    Values v = values_of({static_cast<double>(scan_counter_), static_cast<double>(c)});
    for (std::size_t k = 0; k < kBeamsPerChunk; ++k) {
      const std::size_t beam = c * kBeamsPerChunk + k;
      const bool seen = beam < scan_.beam_count && scan_.valid[beam] && scan_.range[beam] >= 0.001F;
      v.v[2 + k] = seen ? static_cast<double>(scan_.range[beam]) : 0.0;
      v.present[2 + k] = seen;  // absent: raw 0, nothing seen
    }
    send(kLaserRangesId, v);
  }
}

void SoftwareBoard::send_sensors(const hal::SensorFrame& f) noexcept {
  if (f.pose.valid) {
    send(kPoseId, values_of({f.pose.pose.x, f.pose.pose.y, f.pose.pose.theta}));
  } else {
    Values none = values_of({0.0, 0.0, 0.0});
    none.present[0] = none.present[1] = false;
    send(kPoseId, none);
  }
  send(kOdometryId, values_of({f.odometry.distance, f.odometry.velocity, std::clamp(f.odometry.curvature, -32.0, 32.0)}));
  send(kHeadJointsId, values_of({f.head.yaw, f.head.pitch}));
  Values imu = values_of({f.body.tilt.pitch, f.body.tilt.roll});
  imu.present[0] = imu.present[1] = f.body.valid;
  send(kInertialId, imu);
  send(kBumperId, values_of({f.collided ? 1.0 : 0.0}));
}

void SoftwareBoard::step(hal::Nanos now) noexcept {
  ++counts_.steps;
  take_commands(now);
  // The watchdog: no command for command_timeout stops the car, once per silence.
  const bool silent = now - last_command_ > settings_.command_timeout;
  if (state_ != BoardState::kSafe) {
    if (silent && commanded_) {
      ++counts_.watchdog_stops;
      ++faults_;
      commanded_ = false;
      const double ms = static_cast<double>((now - last_command_).count()) / 1e6;
      send(kBoardFaultId, values_of({static_cast<double>(BoardFault::kCommandTimeout), std::min(ms, 65535.0)}));
    }
    state_ = silent ? (counts_.commands > 0 ? BoardState::kWatchdogStop : BoardState::kReady) : BoardState::kDriving;
  }
  if (state_ != BoardState::kDriving) command_.drive = {};
  robot_.actuators().write(command_);
  (void)robot_.sensors().read(frame_);  // the world advances one period
  send_sensors(frame_);
  // Due in the first step and every n-th after it.
  const auto every = [&](int n) { return n > 0 && (counts_.steps - 1) % static_cast<std::uint64_t>(n) == 0; };
  if (every(settings_.heartbeat_every)) {
    send(kBoardHeartbeatId, values_of({static_cast<double>(heartbeat_counter_++), static_cast<double>(state_), static_cast<double>(faults_),
                                                static_cast<double>(drive_counter_)}));
  }
  if (every(settings_.power_every)) {
    send(kPowerId, values_of({std::clamp(frame_.power.battery_volts, 0.0, 65.0), std::clamp(frame_.power.bus_volts, 0.0, 65.0)}));
  }
  if (every(settings_.laser_every) && frame_.laser.beam_count > 0) start_laser(frame_.laser);
  send_laser_slice();
}

}  // namespace ringlet::sim_hal
