#pragma once
// The clock the executive schedules by. Two implementations: MonotonicClock (the real one,
// sleeping with clock_nanosleep on absolute deadlines) and VirtualClock (lockstep simulation and
// tests: time moves only when someone moves it).
#include "ringlet/hal/time.hpp"

namespace ringlet::hal {

class Clock {
 public:
  virtual ~Clock() = default;
  /// Monotonic time now.
  [[nodiscard]] virtual Nanos now() const noexcept = 0;
  /// Block until `deadline` (absolute, on this clock). Returns at once if it has passed.
  virtual void sleep_until(Nanos deadline) noexcept = 0;
};

/// Measures how long work took: wall time and the calling thread's CPU time. The executive
/// measures every task with one of these; in a fully virtual run both readings come from the
/// virtual clock so that injected costs are what the statistics see.
class Stopwatch {
 public:
  virtual ~Stopwatch() = default;
  [[nodiscard]] virtual Nanos wall_now() const noexcept = 0;
  [[nodiscard]] virtual Nanos cpu_now() const noexcept = 0;
};

}  // namespace ringlet::hal
