#pragma once
// atan2 from +, −, ×, ÷ and sqrt alone, each correctly rounded by IEEE 754, so the result is the
// same bits on every host. libm's atan2 differs in its last bits between glibc's x86-64 (FMA)
// and aarch64 code paths, and a lockstep run whose decisions read it would then differ too.
// Accuracy: a few ulp (three half-angle reductions, then a Taylor series to x^25 with |x| < 0.05).
#include <cmath>
#include <numbers>

namespace ringlet::hal {

namespace detail {
/// atan(x) for 0 <= x <= 1.
[[nodiscard]] inline double portable_atan_unit(double x) noexcept {
  // atan(x) = 2 atan(x / (1 + sqrt(1 + x²))): three halvings take x from ≤ 1 to < 0.05.
  double scale = 1.0;
  for (int i = 0; i < 3; ++i) {
    x = x / (1.0 + std::sqrt(1.0 + x * x));
    scale *= 2.0;
  }
  const double x2 = x * x;
  double sum = 0.0;
  for (int k = 25; k >= 3; k -= 2) sum = (k % 4 == 1 ? 1.0 : -1.0) / k + x2 * sum;  // Horner, odd terms
  return scale * (x + x * x2 * sum);
}
}  // namespace detail

/// The angle of (x, y) from the +x axis, in [−π, π], as std::atan2(y, x); atan2(0, 0) = 0.
[[nodiscard]] inline double portable_atan2(double y, double x) noexcept {
  constexpr double kPi = std::numbers::pi;
  const double ax = x < 0.0 ? -x : x;
  const double ay = y < 0.0 ? -y : y;
  if (ax == 0.0 && ay == 0.0) return 0.0;
  double a = ay <= ax ? detail::portable_atan_unit(ay / ax) : kPi / 2 - detail::portable_atan_unit(ax / ay);
  if (x < 0.0) a = kPi - a;
  return y < 0.0 ? -a : a;
}

}  // namespace ringlet::hal
