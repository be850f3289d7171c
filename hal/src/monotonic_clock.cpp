#include "ringlet/hal/monotonic_clock.hpp"

#include <cerrno>
#include <ctime>

namespace ringlet::hal {
namespace {

Nanos read(clockid_t id) noexcept {
  timespec ts{};
  clock_gettime(id, &ts);
  return Nanos{static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec};
}

}  // namespace

Nanos MonotonicClock::now() const noexcept { return read(CLOCK_MONOTONIC); }

void MonotonicClock::sleep_until(Nanos deadline) noexcept {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(deadline.count() / 1'000'000'000);
  ts.tv_nsec = static_cast<long>(deadline.count() % 1'000'000'000);
  // Absolute deadline: a signal interrupting the sleep just resumes towards the same instant.
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
  }
}

Nanos ThreadStopwatch::wall_now() const noexcept { return read(CLOCK_MONOTONIC); }
Nanos ThreadStopwatch::cpu_now() const noexcept { return read(CLOCK_THREAD_CPUTIME_ID); }

}  // namespace ringlet::hal
