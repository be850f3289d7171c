#pragma once
// Noise for the filter from the project's PRNG (hal::SplitMix64), with integer-exact uniforms and
// plain arithmetic only: the same sequence on every target and every standard library (a
// std::normal_distribution's algorithm is the library's choice).
#include <cstdint>

#include "ringlet/hal/splitmix64.hpp"

namespace ringlet::localization {

/// Uniform in [0, 1): the top 53 bits of one draw.
inline double uniform(hal::SplitMix64& rng) noexcept {
  return static_cast<double>(rng.next() >> 11) * 0x1.0p-53;
}

/// Approximately standard normal: the Irwin–Hall sum of four uniforms, centred and scaled to unit
/// variance. Bounded at ±3.46: a motion model never draws a wild jump.
inline double standard_normal(hal::SplitMix64& rng) noexcept {
  const double sum = uniform(rng) + uniform(rng) + uniform(rng) + uniform(rng);
  return (sum - 2.0) * 1.7320508075688772;  // sqrt(3): Var(sum of 4 U(0,1)) = 1/3
}

}  // namespace ringlet::localization
