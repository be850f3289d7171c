#include "ringlet/hal/can/can_robot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ringlet::hal::can {
namespace {

constexpr int kHeartbeatEvery = 10;  // writes per CTRL_HEARTBEAT (100 Hz actuate -> 10 Hz)
constexpr int kSafeStateEvery = 10;  // reads per repeated CTRL_SAFE_STATE while latched

}  // namespace

std::unique_ptr<CanRobot> CanRobot::open(const CanSettings& settings, const Clock& clock, std::string& error) {
  CanSocket socket = CanSocket::open(settings.interface, &error);
  if (!socket.is_open()) return nullptr;
  // The interface's name is copied once here; reopening builds no message (no allocation).
  return std::make_unique<CanRobot>(settings, std::move(socket), clock,
                                    [name = settings.interface] { return CanSocket::open(name); });
}

CanRobot::CanRobot(const CanSettings& settings, CanSocket socket, const Clock& clock, std::function<CanSocket()> reopen)
    : settings_(settings), socket_(std::move(socket)), clock_(clock), reopen_(std::move(reopen)), start_(clock.now()) {
  fd_.store(socket_.fd(), std::memory_order_release);
}

bool CanRobot::fresh(Nanos stamp, std::chrono::milliseconds timeout, Nanos now) const noexcept {
  return stamp.count() > 0 && now - stamp <= timeout;
}

void CanRobot::take(const FrameSpec& spec, const Values& v, Nanos now) noexcept {
  switch (spec.id) {
    case kBoardHeartbeatId:
      heartbeat_at_ = now;
      health_.board_state = static_cast<std::uint8_t>(v[1]);
      measure_round_trip(static_cast<std::uint8_t>(v[3]), now);
      break;
    case kBoardFaultId:
      ++health_.board_faults;
      health_.last_fault = static_cast<std::uint16_t>(v[0]);
      break;
    case kPoseId:
      pose_present_ = v.present[0] && v.present[1];
      latest_.pose.pose = {v[0], v[1], v[2]};
      pose_at_ = now;
      break;
    case kOdometryId:
      latest_.odometry.distance = v[0];
      latest_.odometry.velocity = v[1];
      latest_.odometry.curvature = v[2];
      odometry_at_ = now;
      break;
    case kHeadJointsId:
      latest_.head = {v[0], v[1]};
      head_at_ = now;
      break;
    case kInertialId:
      imu_present_ = v.present[0] && v.present[1];
      latest_.body.tilt = {v.present[0] ? v[0] : 0.0, v.present[1] ? v[1] : 0.0};
      imu_at_ = now;
      break;
    case kBumperId:
      latest_.collided = v[0] > 0.5;
      bumper_at_ = now;
      break;
    case kPowerId:
      latest_.power = {v[0], v[1]};
      power_at_ = now;
      break;
    case kLaserHeaderId: {
      if (pending_scan_ >= 0 && pending_chunks_ < pending_needed_) ++health_.incomplete_scans;
      pending_scan_ = static_cast<int>(v[0]);
      pending_.beam_count = static_cast<std::uint16_t>(v[1]);
      pending_.angle_min = v[2];
      pending_.angle_increment = v[3];
      pending_.max_range = v[4];
      pending_.valid.fill(false);
      pending_chunks_ = 0;
      pending_needed_ = (pending_.beam_count + kBeamsPerChunk - 1) / kBeamsPerChunk;
      break;
    }
    case kLaserRangesId: {
      const auto chunk = static_cast<std::size_t>(v[1]);
      // Chunks come in order after their header: anything else breaks the scan.
      if (static_cast<int>(v[0]) != pending_scan_ || chunk != pending_chunks_ || chunk >= pending_needed_) {
        if (pending_scan_ >= 0) ++health_.incomplete_scans;
        pending_scan_ = -1;
        break;
      }
      for (std::size_t k = 0; k < kBeamsPerChunk; ++k) {
        const std::size_t beam = chunk * kBeamsPerChunk + k;
        if (beam >= pending_.beam_count) break;
        pending_.valid[beam] = v.present[2 + k] && v[2 + k] <= pending_.max_range;
        pending_.range[beam] = pending_.valid[beam] ? static_cast<float>(v[2 + k]) : 0.0F;
      }
      if (++pending_chunks_ == pending_needed_) {
        latest_.laser = pending_;
        latest_.laser.stamp = now;
        laser_at_ = now;
        pending_scan_ = -1;
      }
      break;
    }
    default:
      break;  // commands from another controller on the bus: not ours to read
  }
}

void CanRobot::drain(Nanos now) noexcept {
  for (int i = 0; i < settings_.max_frames_per_read; ++i) {
    RawFrame raw;
    const ReceiveStatus st = socket_.receive(raw);
    if (st == ReceiveStatus::kEmpty) return;
    if (st == ReceiveStatus::kFailed) {
      ++health_.socket_failures;
      set_socket(CanSocket{});  // reopened by reconnect()
      return;
    }
    if (st == ReceiveStatus::kBadFrame) {
      ++health_.malformed;
      continue;
    }
    if (st == ReceiveStatus::kErrorFrame) {
      const BusState before = health_.bus;
      health_.bus = socket_.state();
      if (health_.bus != before && health_.bus == BusState::kBusOff) ++health_.bus_off;
      if (health_.bus != before && health_.bus == BusState::kErrorPassive) ++health_.error_passive;
      if (health_.bus == BusState::kBusOff) {
        set_socket(CanSocket{});  // after a bus-off, start over on a fresh socket
        return;
      }
      continue;
    }
    ++health_.frames_received;
    const FrameSpec* spec = nullptr;
    Values v;
    const CodecResult r = decode(raw, spec, v);
    if (r.error == CodecError::kUnknownId) {
      ++health_.unknown_id;
    } else if (!r.ok()) {
      ++health_.malformed;
    } else {
      take(*spec, v, now);
    }
  }
}

void CanRobot::reconnect(Nanos now) noexcept {
  if (socket_.is_open() || !reopen_ || (last_reconnect_.count() > 0 && now - last_reconnect_ < settings_.reconnect_period)) {
    return;
  }
  last_reconnect_ = now;
  set_socket(reopen_());
  if (socket_.is_open()) {
    ++health_.reconnects;
    health_.bus = BusState::kActive;
  }
}

bool CanRobot::read(SensorFrame& out) noexcept {
  const Nanos now = clock_.now();
  reconnect(now);
  drain(now);
  ++reads_;

  // The board's heartbeat: its loss is the safe state (the board stops the car on its own too).
  const bool alive = fresh(heartbeat_at_, settings_.heartbeat_timeout, now) ||
                     (heartbeat_at_.count() == 0 && now - start_ <= settings_.heartbeat_timeout);
  if (!alive && !lost_) {
    ++health_.heartbeat_losses;
    lost_ = true;
    latch_safe_state(SafeReason::kBoardLost);
  }
  lost_ = !alive;
  health_.board_alive = alive && heartbeat_at_.count() > 0;
  if (in_safe_state() && reads_ % kSafeStateEvery == 0) send_safe_state();

  const auto ms = settings_.sensor_timeout;
  out.stamp = now;
  out.pose = latest_.pose;
  out.pose.stamp = pose_at_;
  out.pose.valid = pose_present_ && fresh(pose_at_, ms, now);
  out.odometry = latest_.odometry;
  out.odometry.stamp = odometry_at_;
  out.head = latest_.head;
  out.body = latest_.body;
  out.body.stamp = imu_at_;
  out.body.valid = imu_present_ && fresh(imu_at_, ms, now);
  out.power = latest_.power;
  out.collided = latest_.collided && fresh(bumper_at_, ms, now);
  if (fresh(laser_at_, settings_.laser_timeout, now)) {
    out.laser = latest_.laser;
  } else {
    out.laser.beam_count = 0;  // no scan: nothing seen is not claimed either
    out.laser.stamp = laser_at_;
  }
  const bool stale = !fresh(pose_at_, ms, now) || !fresh(odometry_at_, ms, now) || !fresh(head_at_, ms, now) ||
                     !fresh(laser_at_, settings_.laser_timeout, now);
  if (stale) ++health_.stale_readings;
  return alive;  // the board answers; each stale sensor is marked invalid on its own
}

void CanRobot::measure_round_trip(std::uint8_t drive_counter, Nanos now) noexcept {
  Nanos& sent = drive_sent_at_[drive_counter];
  // A counter sent more than a second ago is a previous lap of the 8-bit counter, not this one.
  const bool ours = sent.count() > 0 && now >= sent && now - sent <= std::chrono::seconds{1};
  const Nanos took = now - sent;
  sent = Nanos{0};  // each command is measured once (a stopped controller's board repeats the echo)
  if (!ours) return;
  const auto us = static_cast<std::uint64_t>(took.count() / 1000);
  ++round_trips_[std::min<std::size_t>(us / kRoundTripBinUs, kRoundTripBins - 1)];
  RoundTrip& rt = health_.round_trip;
  ++rt.samples;
  rt.max_us = std::max(rt.max_us, static_cast<std::uint32_t>(std::min<std::uint64_t>(us, std::numeric_limits<std::uint32_t>::max())));
  // Percentiles from the histogram: the upper edge of the bin holding the rank (never flatters).
  const auto percentile = [&](std::uint64_t per_mille) {
    const std::uint64_t rank = (rt.samples * per_mille + 999) / 1000;
    std::uint64_t seen = 0;
    for (std::size_t b = 0; b < kRoundTripBins; ++b) {
      seen += round_trips_[b];
      if (seen >= rank) return std::min(rt.max_us, static_cast<std::uint32_t>((b + 1) * kRoundTripBinUs));
    }
    return rt.max_us;
  };
  rt.p50_us = percentile(500);
  rt.p99_us = percentile(990);
}

bool CanRobot::send(const FrameSpec& spec, const Values& v) noexcept {
  RawFrame raw;
  if (!encode(spec, v, raw).ok()) {
    ++health_.refused_commands;
    return false;
  }
  send_raw_frame(raw);
  return true;
}

void CanRobot::send_raw_frame(const RawFrame& raw) noexcept {
  switch (socket_.send(raw)) {
    case SendStatus::kSent: ++health_.frames_sent; break;
    case SendStatus::kQueueFull: ++health_.tx_full; break;
    case SendStatus::kFailed: ++health_.socket_failures; break;
  }
}

void CanRobot::write(const ActuatorCommand& cmd) noexcept {
  ++writes_;
  if (writes_ % kHeartbeatEvery == 1) {
    send(*find_frame(kControllerHeartbeatId),
         values_of({static_cast<double>(heartbeat_counter_++), in_safe_state() ? 2.0 : 1.0}));
  }
  if (in_safe_state()) return;  // latched: only CTRL_SAFE_STATE (read) and the stop already sent
  const FrameSpec& drive = *find_frame(kDriveId);
  const auto counter = static_cast<double>(drive_counter_++);
  // A command the board cannot take is a controller bug: stop rather than guess.
  if (!send(drive, values_of({cmd.drive.curvature, cmd.drive.velocity, counter, 1.0}))) {
    send(drive, values_of({0.0, 0.0, counter, 0.0}));
  }
  drive_sent_at_[static_cast<std::uint8_t>(counter)] = clock_.now();
  send(*find_frame(kHeadCommandId), values_of({cmd.head.yaw, cmd.head.pitch}));
}

// CTRL_SAFE_STATE with its reason, and a stop (CTRL_DRIVE with enable 0): what both the latch and
// its repeats send.
bool CanRobot::safe_state_frames(std::uint8_t counter, RawFrame& safe, RawFrame& stop) const noexcept {
  const auto reason = static_cast<double>(safe_reason_.load(std::memory_order_acquire));
  return encode(*find_frame(kSafeStateId), values_of({reason}), safe).ok() &&
         encode(*find_frame(kDriveId), values_of({0.0, 0.0, static_cast<double>(counter), 0.0}), stop).ok();
}

void CanRobot::send_safe_state() noexcept {
  RawFrame safe, stop;
  if (!safe_state_frames(drive_counter_++, safe, stop)) return;
  for (const RawFrame& f : {safe, stop}) send_raw_frame(f);
}

void CanRobot::enter_safe_state() noexcept { latch_safe_state(SafeReason::kPolicy); }

void CanRobot::latch_safe_state(SafeReason reason) noexcept {
  // Any thread (the watchdog, a signal path): the flag, and the stop straight on the descriptor,
  // touching nothing the cycle owns. The cycle repeats it, counted, every kSafeStateEvery reads.
  if (in_safe_state()) return;  // the first reason stands
  safe_reason_.store(reason, std::memory_order_release);
  if (safe_.exchange(true, std::memory_order_acq_rel)) return;
  const int fd = fd_.load(std::memory_order_acquire);
  RawFrame safe, stop;
  if (fd < 0 || !safe_state_frames(0, safe, stop)) return;
  for (const RawFrame& f : {safe, stop}) (void)send_raw(fd, f.id, f.length, f.data.data());
}

void CanRobot::set_socket(CanSocket socket) noexcept {
  fd_.store(-1, std::memory_order_release);
  socket_ = std::move(socket);
  fd_.store(socket_.fd(), std::memory_order_release);
}

}  // namespace ringlet::hal::can
