#pragma once
// The values of the binary's flags that CLI11 cannot check on its own: strict text to number, with
// the range in the message, so that "nan", "-1", "1e300" or "12abc" are refused by name instead of
// wrapping, overflowing or reaching an undefined conversion.
#include <cstdint>
#include <stdexcept>
#include <string_view>

namespace ringlet::firmware {

/// A bad flag value: "--flag: must be ..., got '...'". The binary exits 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// --duration: seconds of schedule time, a finite number with 0 < seconds <= kMaxRunSeconds
/// (config.hpp). Whether the run's recording fits is checked later, with the configuration
/// (run_length_problem).
[[nodiscard]] double parse_duration(std::string_view text);

/// --seed: a decimal integer 0..2^64-1; no sign, no fraction, no exponent, no overflow.
[[nodiscard]] std::uint64_t parse_seed(std::string_view text);

}  // namespace ringlet::firmware
