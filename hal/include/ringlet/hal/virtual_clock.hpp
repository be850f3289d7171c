#pragma once
// A clock that only moves when told to. sleep_until() jumps straight to the deadline, which is
// what makes lockstep simulation run faster than real time; advance() lets tests inject the cost
// of a task. It also serves as a Stopwatch so that a fully virtual run measures injected costs.
#include <atomic>

#include "ringlet/hal/clock.hpp"

namespace ringlet::hal {

class VirtualClock final : public Clock, public Stopwatch {
 public:
  explicit VirtualClock(Nanos start = Nanos{0}) noexcept : now_(start.count()) {}

  [[nodiscard]] Nanos now() const noexcept override { return Nanos{now_.load(std::memory_order_acquire)}; }
  void sleep_until(Nanos deadline) noexcept override {
    if (deadline.count() > now_.load(std::memory_order_relaxed)) {
      now_.store(deadline.count(), std::memory_order_release);
    }
  }
  /// Moves time forward by `d` (d < 0 is ignored: monotonic means monotonic).
  void advance(Nanos d) noexcept {
    if (d.count() > 0) now_.fetch_add(d.count(), std::memory_order_acq_rel);
  }

  [[nodiscard]] Nanos wall_now() const noexcept override { return now(); }
  [[nodiscard]] Nanos cpu_now() const noexcept override { return now(); }

 private:
  std::atomic<std::int64_t> now_;  // atomic: watchdog threads read it while the cycle runs
};

}  // namespace ringlet::hal
