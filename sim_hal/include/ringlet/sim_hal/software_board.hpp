#pragma once
// A software board: the simulated robot (SimRobot) behind the board's CAN protocol
// (hal/can/README.md), so the firmware, unchanged, drives a simulated car through a real
// SocketCAN bus (ringlet-board-sim on vcan0), or through a socketpair in tests.
//
// Like a real board it has its own watchdog: when no CTRL_DRIVE has come for command_timeout it
// stops the car, reports BOARD_FAULT 1 once and beats with state 3 until commands return. A
// CTRL_SAFE_STATE latches the car stopped (state 4) until the board restarts. Every step is one
// period of the simulated world: it takes the commands waiting, runs the watchdog, advances the
// world, and sends the sensor frames that are due (100 Hz sensors, 10 Hz heartbeat and laser,
// 1 Hz power). A scan's range frames are spread over the steps until the next scan.
#include <cstdint>

#include "ringlet/hal/can/can_socket.hpp"
#include "ringlet/hal/time.hpp"
#include "ringlet/sim_hal/sim_robot.hpp"

namespace ringlet::sim_hal {

struct SoftwareBoardSettings {
  hal::Nanos command_timeout{100'000'000};  // the board's watchdog (100 ms)
  int heartbeat_every = 10;                 // steps per BOARD_HEARTBEAT (10 Hz at 100 Hz)
  int laser_every = 10;                     // steps per laser scan
  int power_every = 100;                    // steps per BOARD_POWER
};

struct SoftwareBoardCounts {
  std::uint64_t steps = 0;
  std::uint64_t commands = 0;         // CTRL_DRIVE taken
  std::uint64_t refused = 0;          // frames that did not decode (malformed, unknown ID)
  std::uint64_t watchdog_stops = 0;   // times the watchdog stopped the car
  std::uint64_t frames_sent = 0;
  std::uint64_t tx_full = 0;          // frames dropped on a full transmit queue
};

class SoftwareBoard {
 public:
  SoftwareBoard(SimRobot& robot, hal::can::CanSocket socket, const SoftwareBoardSettings& settings = {});

  /// One period at `now` (the board's own clock): commands in, watchdog, world advanced, sensors out.
  void step(hal::Nanos now) noexcept;

  [[nodiscard]] const SoftwareBoardCounts& counts() const noexcept { return counts_; }
  [[nodiscard]] hal::can::BoardState state() const noexcept { return state_; }
  [[nodiscard]] bool socket_open() const noexcept { return socket_.is_open(); }

 private:
  void take_commands(hal::Nanos now) noexcept;
  void send(std::uint32_t id, const hal::can::Values& v) noexcept;
  void send_sensors(const hal::SensorFrame& f) noexcept;
  void start_laser(const hal::LaserScan& scan) noexcept;
  void send_laser_slice() noexcept;

  SimRobot& robot_;
  hal::can::CanSocket socket_;
  SoftwareBoardSettings settings_;
  SoftwareBoardCounts counts_;
  hal::ActuatorCommand command_{};
  hal::Nanos last_command_{0};
  bool commanded_ = false;  // a CTRL_DRIVE with enable = 1 has come since the last stop
  hal::can::BoardState state_ = hal::can::BoardState::kReady;
  std::uint8_t heartbeat_counter_ = 0;
  std::uint8_t drive_counter_ = 0;  // of the last CTRL_DRIVE taken: echoed in BOARD_HEARTBEAT
  std::uint8_t scan_counter_ = 0;
  std::uint16_t faults_ = 0;
  hal::SensorFrame frame_{};
  hal::LaserScan scan_{};         // the scan being sent, a slice per step
  std::size_t scan_chunks_ = 0;
  std::size_t next_chunk_ = 0;
};

}  // namespace ringlet::sim_hal
