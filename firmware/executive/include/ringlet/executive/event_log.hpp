#pragma once
// Events from the cycle (overruns, failsafe, watchdog) go through a fixed single-producer /
// single-consumer ring (spsc_queue.hpp) so that the cycle never blocks on I/O: a non-real-time
// thread drains and prints them.
#include <cstdint>

#include "ringlet/executive/spsc_queue.hpp"
#include "ringlet/executive/task_table.hpp"

namespace ringlet::executive {

enum class EventKind : std::uint8_t { kOverrun, kFrameOverrun, kFailsafe };

struct Event {
  EventKind kind = EventKind::kOverrun;
  std::uint16_t task = 0;        // index in the table (overrun, failsafe, degrade)
  std::uint64_t frame = 0;
  Nanos measured{0};             // what was measured (task time, frame busy time, stall time)
  Nanos limit{0};                // what it was allowed
  std::uint64_t suppressed = 0;  // warnings of this kind held back by the rate limit since the last one
  int level = 0;                 // degrade level
};

/// The executive's events on their way to the log drain (256 deep).
using EventLog = SpscQueue<Event, 256>;

}  // namespace ringlet::executive
