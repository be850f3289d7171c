#pragma once
// Events from the cycle (overruns, failsafe, watchdog) go through a fixed single-producer /
// single-consumer ring so that the cycle never blocks on I/O: a non-real-time thread drains and
// prints them. If the ring is full the event is dropped and counted, never waited for.
#include <array>
#include <atomic>
#include <cstdint>

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

class EventLog {
 public:
  static constexpr std::size_t kCapacity = 256;

  /// Producer side: the cycle thread only.
  bool push(const Event& e) noexcept;
  /// Consumer side. Returns false when empty.
  bool pop(Event& out) noexcept;
  [[nodiscard]] std::uint64_t dropped() const noexcept { return dropped_.load(std::memory_order_relaxed); }

 private:
  std::array<Event, kCapacity> ring_{};
  std::atomic<std::uint64_t> head_{0};  // next write
  std::atomic<std::uint64_t> tail_{0};  // next read
  std::atomic<std::uint64_t> dropped_{0};
};

}  // namespace ringlet::executive
