#include "number_text.hpp"

#include <array>
#include <charconv>

namespace ringlet::sim_hal::detail {

std::string format_number(double value) {
  std::array<char, 64> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return {buffer.data(), result.ptr};
}

void append_fixed(std::string& out, double value, int decimals) {
  // Room for the largest finite double in fixed notation (309 digits) plus sign and decimals.
  std::array<char, 400> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value, std::chars_format::fixed,
                              decimals);
  if (result.ec != std::errc{}) {
    out.append("nan");  // only reachable with an absurd `decimals`; keeps the output well-formed
    return;
  }
  std::string_view text(buffer.data(), static_cast<std::size_t>(result.ptr - buffer.data()));
  // A tiny negative value rounds to "-0.000"; print it as "0.000" so equal pictures compare equal.
  if (text.starts_with('-') && text.find_first_not_of("-0.") == std::string_view::npos) text.remove_prefix(1);
  out.append(text);
}

}  // namespace ringlet::sim_hal::detail
