#pragma once
// Numbers in the experiments' CSV, Markdown and SVG: fixed decimals, the same text on every host
// for the same double (printf's correctly rounded conversion), and "nan" spelled one way.
#include <cmath>
#include <cstdio>
#include <string>

namespace ringlet::experiments {

[[nodiscard]] inline std::string fixed(double v, int decimals) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s(buf);
  if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);  // no "-0.00"
  return s;
}

/// A p-value: fixed below 1e-4 would read 0.0000; scientific there instead.
[[nodiscard]] inline std::string p_value(double p) {
  if (std::isnan(p)) return "nan";
  if (p >= 1e-4) return fixed(p, 4);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1e", p);
  return buf;
}

}  // namespace ringlet::experiments
