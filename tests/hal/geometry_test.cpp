// The robot-frame convention every layer shares (hal/geometry.hpp), against hand-computed points.
#include <gtest/gtest.h>

#include <numbers>

#include "ringlet/hal/geometry.hpp"

namespace ringlet::hal {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(RobotFrame, FacingNorthAheadIsPlusYLeftIsMinusX) {
  const Pose2 at_origin_north{0.0, 0.0, 0.0};
  const auto ahead = to_robot_frame(at_origin_north, 0.0, 2.0);
  EXPECT_NEAR(ahead.x, 2.0, 1e-12);
  EXPECT_NEAR(ahead.y, 0.0, 1e-12);
  const auto left = to_robot_frame(at_origin_north, -3.0, 0.0);
  EXPECT_NEAR(left.x, 0.0, 1e-12);
  EXPECT_NEAR(left.y, 3.0, 1e-12);
}

TEST(RobotFrame, FacingEastFromAnOffsetPose) {
  // Robot at (1, 1) facing east (theta = +90 deg): the point (1, 3) is 2 m to its left.
  const Pose2 pose{1.0, 1.0, kPi / 2.0};
  const auto p = to_robot_frame(pose, 1.0, 3.0);
  EXPECT_NEAR(p.x, 0.0, 1e-12);
  EXPECT_NEAR(p.y, 2.0, 1e-12);
  const auto q = to_robot_frame(pose, 4.0, 0.0);  // 3 ahead, 1 to the right
  EXPECT_NEAR(q.x, 3.0, 1e-12);
  EXPECT_NEAR(q.y, -1.0, 1e-12);
}

TEST(RobotFrame, HeadYawAtan2LooksAtThePointAndAgreesWithBearing) {
  const Pose2 pose{2.0, -1.0, 0.3};
  const double wx = -4.0;
  const double wy = 5.0;
  const auto p = to_robot_frame(pose, wx, wy);
  // Head yaw is positive to the left; bearing is clockwise from north: they are opposite.
  EXPECT_NEAR(std::atan2(p.y, p.x), -wrap_angle(bearing_to(pose, wx, wy) - pose.theta), 1e-12);
  EXPECT_NEAR(std::hypot(p.x, p.y), std::hypot(wx - pose.x, wy - pose.y), 1e-12);
}

TEST(RobotToWorld, FacingEastLeftIsNorthAndAheadIsEast) {
  const RobotToWorld to_world(Pose2{1.0, 1.0, kPi / 2.0});
  const WorldPoint left = to_world.point(0.0, 2.0);
  EXPECT_NEAR(left.x, 1.0, 1e-12);
  EXPECT_NEAR(left.y, 3.0, 1e-12);
  const WorldPoint q = to_world(RobotPoint{3.0, -1.0});  // 3 ahead, 1 to the right
  EXPECT_NEAR(q.x, 4.0, 1e-12);
  EXPECT_NEAR(q.y, 0.0, 1e-12);
  const WorldPoint d = to_world.direction(3.0, -1.0);  // the same without the translation
  EXPECT_NEAR(d.x, 3.0, 1e-12);
  EXPECT_NEAR(d.y, -1.0, 1e-12);
}

TEST(RobotToWorld, UndoesToRobotFrame) {
  for (const Pose2 pose : {Pose2{2.0, -1.0, 0.3}, Pose2{-4.5, 3.0, -2.9}, Pose2{0.0, 0.0, kPi}}) {
    const RobotPoint p = to_robot_frame(pose, -4.0, 5.0);
    const WorldPoint w = RobotToWorld(pose)(p);
    EXPECT_NEAR(w.x, -4.0, 1e-12);
    EXPECT_NEAR(w.y, 5.0, 1e-12);
  }
}

}  // namespace
}  // namespace ringlet::hal
