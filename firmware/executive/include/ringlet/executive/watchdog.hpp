#pragma once
// The watchdog drives the safe state when the cycle stalls (no frame started for `timeout`) or a
// shutdown is requested (SIGINT/SIGTERM). The decision logic (WatchdogMonitor) is separate from
// the thread that polls it, so tests can run the logic on a virtual clock.
#include <atomic>
#include <cstdint>
#include <thread>

#include "ringlet/hal/clock.hpp"
#include "ringlet/hal/robot.hpp"

namespace ringlet::executive {

using hal::Nanos;

class WatchdogMonitor {
 public:
  explicit WatchdogMonitor(Nanos timeout) noexcept : timeout_(timeout) {}
  /// Feeds one observation of the heartbeat; returns true exactly once, when the heartbeat has
  /// not moved for longer than the timeout.
  bool observe(std::uint64_t heartbeat, Nanos now) noexcept;
  [[nodiscard]] bool tripped() const noexcept { return tripped_; }
  [[nodiscard]] Nanos stalled_for() const noexcept { return stalled_for_; }

 private:
  Nanos timeout_;
  bool seen_ = false;
  bool tripped_ = false;
  std::uint64_t last_beat_ = 0;
  Nanos last_change_{0};
  Nanos stalled_for_{0};
};

/// Polls the heartbeat on `clock` (the real clock, whatever the executive schedules by) every
/// `poll` until stopped. On a stall or when `shutdown` becomes true it commands the safe state.
class WatchdogThread {
 public:
  WatchdogThread(hal::Clock& clock, const std::atomic<std::uint64_t>& heartbeat, hal::Actuators& actuators,
                 Nanos timeout, Nanos poll, const std::atomic<bool>* shutdown = nullptr);
  ~WatchdogThread();
  WatchdogThread(const WatchdogThread&) = delete;
  WatchdogThread& operator=(const WatchdogThread&) = delete;

  /// Stops polling (does not command the safe state).
  void stop() noexcept;
  [[nodiscard]] bool fired() const noexcept { return fired_.load(std::memory_order_acquire); }
  [[nodiscard]] bool shutdown_seen() const noexcept { return shutdown_seen_.load(std::memory_order_acquire); }
  [[nodiscard]] Nanos stalled_for() const noexcept { return Nanos{stalled_ns_.load(std::memory_order_acquire)}; }
  /// The polling thread (named "rl-watchdog"), for its scheduler: set_fifo_priority(handle,
  /// watchdog_priority(cycle's), "watchdog") puts it above the cycle (realtime.hpp).
  [[nodiscard]] std::thread::native_handle_type native_handle() noexcept { return thread_.native_handle(); }

 private:
  void loop() noexcept;

  hal::Clock& clock_;
  const std::atomic<std::uint64_t>& heartbeat_;
  hal::Actuators& actuators_;
  WatchdogMonitor monitor_;
  Nanos poll_;
  const std::atomic<bool>* shutdown_;
  std::atomic<bool> running_{true};
  std::atomic<bool> fired_{false};
  std::atomic<bool> shutdown_seen_{false};
  std::atomic<std::int64_t> stalled_ns_{0};
  std::thread thread_;
};

}  // namespace ringlet::executive
