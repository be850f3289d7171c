#include "ringlet/firmware/command_line.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <string>
#include <system_error>

#include "ringlet/firmware/config.hpp"

namespace ringlet::firmware {
namespace {

// The text as given, shortened: the message must stay one line whatever was typed.
std::string quoted(std::string_view text) {
  constexpr std::size_t kShown = 40;
  return "'" + std::string(text.substr(0, kShown)) + (text.size() > kShown ? "...'" : "'");
}

}  // namespace

double parse_duration(std::string_view text) {
  double seconds = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), seconds);
  std::ostringstream range;
  range << "--duration: must be a number of seconds greater than 0 and at most " << kMaxRunSeconds << ", got "
        << quoted(text);
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size()) throw UsageError(range.str());
  if (!(std::isfinite(seconds) && seconds > 0.0 && seconds <= kMaxRunSeconds)) throw UsageError(range.str());
  return seconds;
}

std::uint64_t parse_seed(std::string_view text) {
  const std::string rule = "--seed: must be a whole number from 0 to 18446744073709551615, got " + quoted(text);
  // from_chars into an unsigned type takes digits only: no sign, no space, and it reports
  // overflow instead of wrapping (strtoull would turn "-1" into 2^64-1).
  std::uint64_t seed = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), seed, 10);
  if (ec == std::errc::result_out_of_range) throw UsageError(rule + " (too large)");
  if (ec != std::errc{} || end != text.data() + text.size()) throw UsageError(rule);
  return seed;
}

}  // namespace ringlet::firmware
