#pragma once
// The real clock: CLOCK_MONOTONIC, sleeping with clock_nanosleep(TIMER_ABSTIME) so that a late
// wake-up never shifts the following deadlines. ThreadStopwatch reads CLOCK_MONOTONIC and the
// calling thread's CLOCK_THREAD_CPUTIME_ID.
#include "ringlet/hal/clock.hpp"

namespace ringlet::hal {

class MonotonicClock final : public Clock {
 public:
  [[nodiscard]] Nanos now() const noexcept override;
  void sleep_until(Nanos deadline) noexcept override;
};

class ThreadStopwatch final : public Stopwatch {
 public:
  [[nodiscard]] Nanos wall_now() const noexcept override;
  [[nodiscard]] Nanos cpu_now() const noexcept override;
};

}  // namespace ringlet::hal
