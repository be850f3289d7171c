// hal::portable_atan2: within a few ulp of libm's atan2 everywhere, exact at the axes' angles, and
// built only from correctly rounded operations (so the same bits on x86-64 and aarch64).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ringlet/hal/portable_atan2.hpp"

namespace ringlet::hal {
namespace {

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

}  // namespace
}  // namespace ringlet::hal
