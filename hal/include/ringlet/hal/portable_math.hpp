#pragma once
// The libm functions whose last bits differ between hosts, rebuilt from +, −, ×, ÷ and sqrt alone,
// each correctly rounded by IEEE 754 (and -ffp-contract=off, cmake/RingletWarnings.cmake), so the
// result is the same bits on every host. A lockstep run whose decisions read libm's would differ
// between x86-64 and aarch64:
//   hypot: glibc 2.36 computes it with FMA on aarch64 and without on x86-64, even on a CPU with
//     FMA: of 2·10⁵ random pairs in ±10, 12.5 % differed in the last bit. The code that runs in
//     the controller uses portable_hypot, never std::hypot (cmake/RingletPortableMath.cmake lists
//     the folders; the test PortableMath.NoLibmHypotInTheController holds them to it).
//   atan2: glibc's x86-64 picks an FMA or a plain kernel by the CPU (ifunc). It agreed with
//     aarch64 on an FMA CPU; the localization's chaotic resampling uses portable_atan2 regardless.
// sin, cos, tan, atan, exp, log and pow agreed bit for bit over 2·10⁶ inputs between x86-64 (with
// FMA) and aarch64 (qemu); they are used as they are.
#include <cmath>
#include <numbers>

namespace ringlet::hal {

/// sqrt(x² + y²), within 1 ulp of std::hypot. No guard against overflow or underflow of the
/// squares: for |x|, |y| between 1e−150 and 1e150 (metres, pixels, velocities).
[[nodiscard]] inline double portable_hypot(double x, double y) noexcept { return std::sqrt(x * x + y * y); }

/// The same for a 3-vector.
[[nodiscard]] inline double portable_hypot(double x, double y, double z) noexcept {
  return std::sqrt(x * x + y * y + z * z);
}

namespace detail {
/// atan(x) for 0 <= x <= 1, within a few ulp: three half-angle reductions, then a Taylor series
/// to x^25 with |x| < 0.05.
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
