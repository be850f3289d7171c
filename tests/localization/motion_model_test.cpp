// Odometry: deltas in the robot frame (hal/geometry.hpp's heading convention), dead reckoning of
// an arc, the latency transform, and the noise generator.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ringlet/localization/gaussian.hpp"
#include "ringlet/localization/motion_model.hpp"

namespace ringlet::localization {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

TEST(LocalizationMotion, DeltaIsInTheRobotFrameOfTheStart) {
  // θ = 0 faces +y, left is −x.
  const OdometryDelta ahead = delta_between({0, 0, 0}, {0, 1, 0});
  EXPECT_NEAR(ahead.forward, 1.0, 1e-12);
  EXPECT_NEAR(ahead.left, 0.0, 1e-12);
  const OdometryDelta left = delta_between({0, 0, 0}, {-1, 0, 0});
  EXPECT_NEAR(left.left, 1.0, 1e-12);
  const OdometryDelta east = delta_between({0, 0, kHalfPi}, {1, 0, kHalfPi + 0.3});
  EXPECT_NEAR(east.forward, 1.0, 1e-12);
  EXPECT_NEAR(east.turn, 0.3, 1e-12);
  const hal::Pose2 from{1.0, -2.0, 0.7};
  const hal::Pose2 to{2.5, 0.5, -2.9};
  const hal::Pose2 back = apply(from, delta_between(from, to));
  EXPECT_NEAR(back.x, to.x, 1e-12);
  EXPECT_NEAR(back.y, to.y, 1e-12);
  EXPECT_NEAR(back.theta, to.theta, 1e-12);
}

TEST(LocalizationMotion, LatencyTransformOfAPoint) {
  const hal::RobotPoint a = transform_point({1.0, 0.0, 0.0}, 2.0, 0.0);  // drove 1 m towards it
  EXPECT_NEAR(a.x, 1.0, 1e-12);
  EXPECT_NEAR(a.y, 0.0, 1e-12);
  const hal::RobotPoint b = transform_point({0.0, 0.0, kHalfPi}, 1.0, 0.0);  // turned right 90°
  EXPECT_NEAR(b.x, 0.0, 1e-12);
  EXPECT_NEAR(b.y, 1.0, 1e-12);  // what was ahead is now on the left
}

TEST(LocalizationMotion, DeadReckoningOfAQuarterCircle) {
  OdometryIntegrator odo;
  odo.add(0.0, 1.0);
  const int steps = 2000;
  for (int i = 1; i <= steps; ++i) odo.add(kHalfPi * i / steps, 1.0);  // radius 1, κ > 0 turns clockwise
  EXPECT_NEAR(odo.pose().x, 1.0, 1e-6);  // from facing +y to facing +x round the centre (1, 0)
  EXPECT_NEAR(odo.pose().y, 1.0, 1e-6);
  EXPECT_NEAR(odo.pose().theta, kHalfPi, 1e-9);
}

TEST(LocalizationMotion, NoiseIsSeededUnitAndProportional) {
  hal::SplitMix64 a(7), b(7);
  double sum = 0.0, sum2 = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double x = standard_normal(a);
    ASSERT_EQ(x, standard_normal(b));
    sum += x;
    sum2 += x * x;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.03);
  EXPECT_NEAR(sum2 / n, 1.0, 0.03);
  MotionNoise none{0, 0, 0, 0, 0, 0};
  const OdometryDelta d{0.3, 0.01, 0.2};
  const OdometryDelta same = noisy(d, none, a);
  EXPECT_EQ(same.forward, d.forward);
  EXPECT_EQ(same.turn, d.turn);
}

}  // namespace
}  // namespace ringlet::localization
