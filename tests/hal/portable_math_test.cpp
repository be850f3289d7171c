// hal/portable_math.hpp: portable_atan2 within a few ulp of libm's atan2 everywhere and exact at the
// axes' angles; portable_hypot within 1 ulp of libm's hypot. Both are built only from correctly
// rounded operations, so they give the same bits on x86-64 and aarch64.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "ringlet/hal/portable_math.hpp"

namespace ringlet::hal {
namespace {

// The gap from `x` to the next double up: one unit in the last place.
double ulp(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()) - x; }

TEST(PortableAtan2, AgreesWithLibmAllRoundTheCircle) {
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const double a = -std::numbers::pi + 2.0 * std::numbers::pi * (i + 0.37) / 20000.0;
    for (const double r : {1e-6, 0.3, 1.0, 7.5, 1e6}) {
      const double y = r * std::sin(a), x = r * std::cos(a);
      worst = std::max(worst, std::fabs(portable_atan2(y, x) - std::atan2(y, x)));
    }
  }
  EXPECT_LT(worst, 4e-15) << "a few ulp of pi";
}

TEST(PortableAtan2, AxesAndQuadrants) {
  EXPECT_EQ(portable_atan2(0.0, 0.0), 0.0);
  EXPECT_EQ(portable_atan2(0.0, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(portable_atan2(3.0, 0.0), std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(portable_atan2(-3.0, 0.0), -std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(portable_atan2(0.0, -1.0), std::numbers::pi);
  EXPECT_DOUBLE_EQ(portable_atan2(1.0, 1.0), std::numbers::pi / 4);
  EXPECT_DOUBLE_EQ(portable_atan2(-1.0, -1.0), -3.0 * std::numbers::pi / 4);
}

TEST(PortableHypot, WithinAnUlpOfLibm) {
  std::uint64_t state = 7;
  const auto next = [&state] {  // a small LCG: any spread of inputs will do
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  for (int i = 0; i < 100000; ++i) {
    const double scale = std::ldexp(1.0, static_cast<int>(next() * 80.0) - 40);  // 1e-12 … 1e12
    const double x = (2.0 * next() - 1.0) * scale, y = (2.0 * next() - 1.0) * scale;
    const double want = std::hypot(x, y);
    const double got = portable_hypot(x, y);
    ASSERT_LE(std::fabs(got - want), ulp(want)) << x << ", " << y;
    const double z = (2.0 * next() - 1.0) * scale;
    const double want3 = std::hypot(x, y, z);
    ASSERT_LE(std::fabs(portable_hypot(x, y, z) - want3), 2.0 * ulp(want3))
        << x << ", " << y << ", " << z;
  }
}

TEST(PortableHypot, ExactWhereTheSquaresAre) {
  EXPECT_EQ(portable_hypot(3.0, 4.0), 5.0);
  EXPECT_EQ(portable_hypot(-3.0, -4.0), 5.0);
  EXPECT_EQ(portable_hypot(0.0, -2.5), 2.5);
  EXPECT_EQ(portable_hypot(2.0, 3.0, 6.0), 7.0);
  EXPECT_EQ(portable_hypot(0.0, 0.0), 0.0);
}

}  // namespace
}  // namespace ringlet::hal
