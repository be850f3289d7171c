#pragma once
// Time in Ringlet is always a count of nanoseconds on some monotonic clock, held in a
// std::chrono::nanoseconds so units cannot be mixed up. Whose clock it is (real or virtual)
// is decided by the Clock that produced it.
#include <chrono>
#include <cstdint>

namespace ringlet::hal {

using Nanos = std::chrono::nanoseconds;

constexpr double to_seconds(Nanos t) noexcept { return std::chrono::duration<double>(t).count(); }
constexpr Nanos from_micros(std::int64_t us) noexcept { return std::chrono::microseconds(us); }

}  // namespace ringlet::hal
