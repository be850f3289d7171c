// Eq. (18) in closed form, and the clamping and rate limiting of step_car.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "ringlet/sim_hal/kinematics.hpp"

namespace ringlet::sim_hal {
namespace {

using hal::Pose2;
constexpr double kPi = std::numbers::pi;

/// Eq. (18) solved the textbook way, for kappa != 0.
Pose2 textbook_arc(const Pose2& p, double kappa, double v, double t) {
  const double theta1 = p.theta + v * kappa * t;
  return {p.x + (std::cos(p.theta) - std::cos(theta1)) / kappa, p.y + (std::sin(theta1) - std::sin(p.theta)) / kappa,
          hal::wrap_angle(theta1)};
}

void expect_pose_near(const Pose2& actual, const Pose2& expected, double tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(hal::wrap_angle(actual.theta - expected.theta), 0.0, tolerance);
}

TEST(SimKinematics, StraightLineFollowsTheHeading) {
  const Pose2 start{1.0, 2.0, hal::deg_to_rad(30.0)};
  const Pose2 end = integrate_arc(start, 0.0, 2.0, 1.5);  // 3 m at a bearing of 30 degrees
  expect_pose_near(end, {1.0 + 1.5, 2.0 + 3.0 * std::cos(kPi / 6.0), kPi / 6.0}, 1e-12);
}

TEST(SimKinematics, NorthIsPlusYAndEastIsPlusX) {
  expect_pose_near(integrate_arc({0.0, 0.0, 0.0}, 0.0, 1.0, 1.0), {0.0, 1.0, 0.0}, 1e-15);
  expect_pose_near(integrate_arc({0.0, 0.0, kPi / 2.0}, 0.0, 1.0, 1.0), {1.0, 0.0, kPi / 2.0}, 1e-15);
}

TEST(SimKinematics, QuarterCircleWithPositiveCurvatureTurnsClockwise) {
  const Pose2 end = integrate_arc({0.0, 0.0, 0.0}, 1.0, 1.0, kPi / 2.0);
  expect_pose_near(end, {1.0, 1.0, kPi / 2.0}, 1e-12);
}

TEST(SimKinematics, NegativeCurvatureTurnsTheOtherWay) {
  const Pose2 end = integrate_arc({0.0, 0.0, 0.0}, -1.0, 1.0, kPi / 2.0);
  expect_pose_near(end, {-1.0, 1.0, -kPi / 2.0}, 1e-12);
}

TEST(SimKinematics, ReversingRetracesTheArc) {
  const Pose2 start{3.0, -2.0, 0.4};
  const Pose2 there = integrate_arc(start, 0.8, 1.2, 2.0);
  expect_pose_near(integrate_arc(there, 0.8, -1.2, 2.0), start, 1e-12);
}

TEST(SimKinematics, MatchesTheTextbookClosedForm) {
  struct Case {
    Pose2 start;
    double kappa;
    double v;
    double t;
  };
  const Case cases[] = {
      {{0.0, 0.0, 0.0}, 0.5, 1.0, 3.0},   {{2.0, -1.0, 1.0}, -2.0, 0.7, 1.1}, {{-4.0, 3.0, -2.5}, 1.3, -0.9, 4.0},
      {{1.0, 1.0, 3.0}, 0.01, 1.0, 10.0}, {{0.0, 5.0, 0.2}, -0.3, 2.0, 7.5},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << "kappa " << c.kappa << " v " << c.v << " t " << c.t);
    expect_pose_near(integrate_arc(c.start, c.kappa, c.v, c.t), textbook_arc(c.start, c.kappa, c.v, c.t), 1e-10);
  }
}

TEST(SimKinematics, ThetaIsWrapped) {
  const Pose2 end = integrate_arc({0.0, 0.0, 3.0}, 1.0, 1.0, 1.0);  // 3 + 1 rad goes past pi
  EXPECT_GT(end.theta, -kPi);
  EXPECT_LE(end.theta, kPi);
  EXPECT_NEAR(end.theta, 4.0 - 2.0 * kPi, 1e-12);
}

TEST(SimKinematics, NoJumpAtTheStraightLineLimit) {
  const Pose2 start{0.0, 0.0, 0.7};
  const Pose2 straight = integrate_arc(start, 0.0, 1.0, 1.0);
  // Over 1 m an arc of curvature kappa leaves the straight line sideways by about kappa / 2.
  for (const double kappa : {1e-2, 1e-4, 2e-4, 1e-6, 1e-9, 1e-12, -1e-9}) {
    SCOPED_TRACE(kappa);
    const Pose2 arc = integrate_arc(start, kappa, 1.0, 1.0);
    EXPECT_LE(std::hypot(arc.x - straight.x, arc.y - straight.y), 0.5 * std::fabs(kappa) * 1.001 + 1e-15);
  }
  // Either side of the series threshold inside the implementation (half-turn 1e-4) the results
  // must agree to rounding: a discontinuity there would show up as a jump here.
  const Pose2 below = integrate_arc(start, 2e-4 * (1.0 - 1e-9), 1.0, 1.0);
  const Pose2 above = integrate_arc(start, 2e-4 * (1.0 + 1e-9), 1.0, 1.0);
  EXPECT_LT(std::hypot(above.x - below.x, above.y - below.y), 1e-12);
}

TEST(SimKinematics, ManySmallStepsEqualOneBigStep) {
  const Pose2 start{1.0, -3.0, -0.3};
  Pose2 stepped = start;
  for (int i = 0; i < 1000; ++i) stepped = integrate_arc(stepped, -0.9, 1.1, 0.004);
  expect_pose_near(stepped, integrate_arc(start, -0.9, 1.1, 4.0), 1e-9);
}

TEST(SimKinematics, AgreesWithFineEulerIntegrationOfEq18) {
  const Pose2 start{0.5, 0.5, 2.0};
  const double kappa = 0.7;
  const double v = 1.3;
  const double dt = 1e-5;
  Pose2 euler = start;
  for (int i = 0; i < 300'000; ++i) {  // 3 s
    euler.x += v * std::sin(euler.theta) * dt;
    euler.y += v * std::cos(euler.theta) * dt;
    euler.theta += v * kappa * dt;
  }
  expect_pose_near(integrate_arc(start, kappa, v, 3.0), euler, 1e-4);
}

TEST(SimKinematics, StepCarClampsTheCommandToTheLimits) {
  CarLimits limits;
  limits.max_acceleration = 1e9;  // no rate limiting in this test
  limits.max_curvature_rate = 1e9;
  const CarState forward = step_car({}, {.curvature = -10.0, .velocity = 5.0}, limits, 0.01);
  EXPECT_DOUBLE_EQ(forward.velocity, limits.max_speed);
  EXPECT_DOUBLE_EQ(forward.curvature, -limits.max_curvature);
  const CarState backward = step_car({}, {.curvature = 3.0, .velocity = -7.0}, limits, 0.01);
  EXPECT_DOUBLE_EQ(backward.velocity, -limits.max_speed);
  EXPECT_DOUBLE_EQ(backward.curvature, limits.max_curvature);
}

TEST(SimKinematics, StepCarRateLimitsSpeedAndCurvature) {
  CarLimits limits;
  limits.max_acceleration = 1.0;
  limits.max_curvature_rate = 4.0;
  const CarState next = step_car({}, {.curvature = 2.0, .velocity = 1.0}, limits, 0.01);
  EXPECT_DOUBLE_EQ(next.velocity, 0.01);
  EXPECT_DOUBLE_EQ(next.curvature, 0.04);
  // The pose moves with the new (kappa, v), not the old (0, 0).
  expect_pose_near(next.pose, integrate_arc({}, 0.04, 0.01, 0.01), 1e-15);
  EXPECT_GT(next.pose.y, 0.0);
}

TEST(SimKinematics, StepCarSettlesExactlyOnTheTarget) {
  CarState state;
  for (int i = 0; i < 150; ++i) state = step_car(state, {.curvature = -0.5, .velocity = 0.8}, CarLimits{}, 0.01);
  EXPECT_EQ(state.velocity, 0.8);
  EXPECT_EQ(state.curvature, -0.5);
}

TEST(SimKinematics, StepCarReadsANonFiniteCommandAsStop) {
  CarState state;
  state.velocity = 0.5;
  state.curvature = 0.3;
  const CarState next = step_car(state, {.curvature = std::nan(""), .velocity = std::numeric_limits<double>::infinity()}, CarLimits{}, 0.01);
  EXPECT_DOUBLE_EQ(next.velocity, 0.49);
  EXPECT_DOUBLE_EQ(next.curvature, 0.26);
  EXPECT_TRUE(std::isfinite(next.pose.x));
}

}  // namespace
}  // namespace ringlet::sim_hal
