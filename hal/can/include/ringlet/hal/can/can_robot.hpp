#pragma once
// The real board over SocketCAN (hal/can/README.md): a hal::Robot whose sensors are the board's
// frames and whose actuators are CTRL_DRIVE / CTRL_HEAD.
//
// read() (the sense task) drains the receive queue, at most max_frames_per_read frames, decodes
// each into the latest value of its sensor with the time it arrived, and fills the SensorFrame:
// a sensor older than its timeout is marked invalid (stale). write() (the actuate task) sends the
// drive and head commands, and a heartbeat every tenth call. Nothing allocates after start-up and
// nothing blocks: a full transmit queue is counted and the frame dropped (the next cycle sends a
// newer one).
//
// Every fault has a defined response, counted in BoardHealth:
//   stale sensor           the sensor is invalid in that frame's reading
//   missed board heartbeat the safe state (latched; CTRL_SAFE_STATE sent), board_lost()
//   bus-off / error-passive counted, state kept; after a bus-off the socket is reopened
//   full transmit queue    counted, frame dropped
//   malformed frame        counted, ignored (the sensor keeps its last good value and ages)
//   unknown ID             counted, ignored
//   socket failure         counted; the socket is reopened every reconnect_period
#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "ringlet/hal/board_health.hpp"
#include "ringlet/hal/can/can_socket.hpp"
#include "ringlet/hal/can/protocol.hpp"
#include "ringlet/hal/clock.hpp"
#include "ringlet/hal/robot.hpp"

namespace ringlet::hal::can {

using hal::BoardHealth;

struct CanSettings {
  std::string interface = "can0";
  std::chrono::milliseconds heartbeat_timeout{300};  // the board beats at 10 Hz
  std::chrono::milliseconds sensor_timeout{50};      // the 100 Hz sensors
  std::chrono::milliseconds laser_timeout{300};      // the 10 Hz laser
  std::chrono::milliseconds reconnect_period{500};
  int max_frames_per_read = 4096;  // bounds the drain: a babbling bus cannot hold the cycle
};

class CanRobot final : public Robot, private Sensors, private Actuators {
 public:
  /// Opens `settings.interface` (false and `error` when it cannot).
  static std::unique_ptr<CanRobot> open(const CanSettings& settings, const Clock& clock, std::string& error);
  /// Over a given socket; `reopen` makes a new one after a failure or a bus-off (may return a
  /// closed socket: tried again every reconnect_period).
  CanRobot(const CanSettings& settings, CanSocket socket, const Clock& clock, std::function<CanSocket()> reopen);

  [[nodiscard]] std::string_view backend_name() const noexcept override { return "can"; }
  Sensors& sensors() noexcept override { return *this; }
  Actuators& actuators() noexcept override { return *this; }
  Camera* camera() noexcept override { return nullptr; }

  [[nodiscard]] const BoardHealth& health() const noexcept { return health_; }
  [[nodiscard]] const BoardHealth* board_health() const noexcept override { return &health_; }
  /// True while no board heartbeat has come for heartbeat_timeout.
  [[nodiscard]] bool board_lost() const noexcept { return lost_; }

 private:
  bool read(SensorFrame& out) noexcept override;
  void write(const ActuatorCommand& cmd) noexcept override;
  void enter_safe_state() noexcept override;
  [[nodiscard]] bool in_safe_state() const noexcept override { return safe_.load(std::memory_order_acquire); }

  void drain(Nanos now) noexcept;
  void measure_round_trip(std::uint8_t drive_counter, Nanos now) noexcept;
  void take(const FrameSpec& spec, const Values& v, Nanos now) noexcept;
  /// False (counted as refused, nothing sent) when the values are outside the protocol.
  bool send(const FrameSpec& spec, const Values& v) noexcept;
  void send_raw_frame(const RawFrame& raw) noexcept;  // sent, queue full or failed: counted
  bool safe_state_frames(std::uint8_t counter, RawFrame& safe, RawFrame& stop) const noexcept;
  void send_safe_state() noexcept;
  void latch_safe_state(SafeReason reason) noexcept;
  void reconnect(Nanos now) noexcept;
  void set_socket(CanSocket socket) noexcept;
  [[nodiscard]] bool fresh(Nanos stamp, std::chrono::milliseconds timeout, Nanos now) const noexcept;

  CanSettings settings_;
  CanSocket socket_;
  const Clock& clock_;
  std::function<CanSocket()> reopen_;
  BoardHealth health_;
  std::atomic<bool> safe_{false};
  std::atomic<SafeReason> safe_reason_{SafeReason::kPolicy};  // why the safe state was latched
  std::atomic<int> fd_{-1};  // the socket's descriptor, for enter_safe_state from another thread
  bool lost_ = false;
  Nanos start_{0};
  Nanos last_reconnect_{0};
  std::uint64_t reads_ = 0;
  std::uint64_t writes_ = 0;
  std::uint8_t drive_counter_ = 0;
  std::uint8_t heartbeat_counter_ = 0;
  // When each CTRL_DRIVE counter value was last sent (0: not sent, or already measured), and the
  // round trips seen, in kRoundTripBinUs bins up to kRoundTripBins (the last bin: beyond).
  static constexpr std::uint32_t kRoundTripBinUs = 250;
  static constexpr std::size_t kRoundTripBins = 2000;
  std::array<Nanos, 256> drive_sent_at_{};
  std::array<std::uint32_t, kRoundTripBins> round_trips_{};

  // The latest value of each sensor and when it arrived (0: never).
  SensorFrame latest_{};
  Nanos pose_at_{0}, odometry_at_{0}, head_at_{0}, imu_at_{0}, bumper_at_{0}, power_at_{0}, laser_at_{0}, heartbeat_at_{0};
  bool pose_present_ = false, imu_present_ = false;
  // The scan being received: its number, and which chunks have come.
  LaserScan pending_{};
  int pending_scan_ = -1;
  std::size_t pending_chunks_ = 0;
  std::size_t pending_needed_ = 0;
};

}  // namespace ringlet::hal::can
