#pragma once
// The link to a real board, as the controller sees it: what a backend with a board (hal/can's
// CanRobot) counts, and hal::Robot::board_health() hands to the firmware, which posts it on the
// whiteboard (wb::BoardHealth) and puts it in the report. Backends without a board (the simulator,
// a replay) have none.
#include <cstdint>

namespace ringlet::hal {

enum class BusState : std::uint8_t { kActive, kErrorPassive, kBusOff };

// The command -> board -> sensor round trip: from sending a CTRL_DRIVE to reading the
// BOARD_HEARTBEAT that says the board had applied it before that step's sensor frames. It includes
// the wait for the next sense activation (up to one period), as every command's effect does.
struct RoundTrip {
  std::uint64_t samples = 0;
  std::uint32_t p50_us = 0;
  std::uint32_t p99_us = 0;
  std::uint32_t max_us = 0;
};

struct BoardHealth {
  std::uint64_t frames_received = 0;
  std::uint64_t frames_sent = 0;
  std::uint64_t malformed = 0;       // wrong length, value out of range, not a standard data frame
  std::uint64_t unknown_id = 0;
  std::uint64_t stale_readings = 0;  // reads in which at least one sensor was stale
  std::uint64_t heartbeat_losses = 0;
  std::uint64_t bus_off = 0;
  std::uint64_t error_passive = 0;
  std::uint64_t tx_full = 0;
  std::uint64_t socket_failures = 0;
  std::uint64_t reconnects = 0;
  std::uint64_t refused_commands = 0;  // commands outside the protocol's ranges (not sent; a stop is)
  std::uint64_t board_faults = 0;      // faults the board reported
  std::uint16_t last_fault = 0;
  std::uint64_t incomplete_scans = 0;  // laser scans with a part missing
  RoundTrip round_trip;
  BusState bus = BusState::kActive;
  std::uint8_t board_state = 0;        // the board's own state, as its heartbeat says
  bool board_alive = false;
};

}  // namespace ringlet::hal
