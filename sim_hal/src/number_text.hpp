#pragma once
// Locale-independent number formatting for messages and SVG output: std::to_chars never looks at
// the global locale, so the same value always produces the same bytes.
#include <string>

namespace ringlet::sim_hal::detail {

/// Shortest text that reads back as the same double: 0.5, -1, 1e+300, inf.
[[nodiscard]] std::string format_number(double value);

/// Appends `value` with exactly `decimals` digits after the point; never prints "-0.000".
void append_fixed(std::string& out, double value, int decimals);

}  // namespace ringlet::sim_hal::detail
