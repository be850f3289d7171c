// Ground truth against geometry worked out by hand: a robot on the centre line looking along it,
// a line across the view cut by the image's sides, the ball's projection, and occlusion.
#include <gtest/gtest.h>

#include <cmath>

#include "camera_test_support.hpp"
#include "ringlet/sim_hal/camera_renderer.hpp"

namespace ringlet::sim_hal {
namespace {

constexpr double kPitch = 0.3;
const hal::HeadJoints kHead{0.0, kPitch};
constexpr double kSample = 0.011;  // truth samples are at most 1 cm apart, plus rounding

/// The default mount's camera at head pitch p, in the robot frame (x ahead, z up), written out
/// from the mount: pivot at 0.45 m, the lens 0.05 m ahead of and 0.06 m above it in the head.
struct HandCamera {
  double x = 0.05 * std::cos(kPitch) + 0.06 * std::sin(kPitch);
  double z = 0.45 - 0.05 * std::sin(kPitch) + 0.06 * std::cos(kPitch);
};

/// A robot standing on the centre line (x = 0) of a field, looking north along it.
World centre_line_world() {
  World world = test::open_field();
  world.markings.push_back(Marking{{0.0, -3.0}, {0.0, 3.0}, 0.05});
  world.rings.push_back(Ring{{0.0, 0.0}, 0.75, 0.05});
  return world;
}
const hal::Pose2 kOnCentreLine{0.0, -2.5, 0.0};  // robot x = world y + 2.5, robot y = -world x

TEST(SimCameraTruth, CentreLineSeenFromTheBottomEdgeToItsEnd) {
  CameraRenderer r(centre_line_world(), CameraSpec{}, 1);
  r.render(kOnCentreLine, kHead);
  const FrameTruth& truth = r.truth();
  const hal::CameraIntrinsics k = hal::CameraIntrinsics::nao();
  const HandCamera cam;

  ASSERT_EQ(truth.lines.size(), 1U);
  const LineRunTruth& run = truth.lines[0];
  EXPECT_EQ(run.marking, 0U);
  // Nearest visible point: the bottom edge's ray, pitch + atan(cy / fy) below the horizon.
  const double bottom = kPitch + std::atan(k.cy / k.fy);
  const double near = cam.x + cam.z / std::tan(bottom);
  EXPECT_NEAR(run.ground_a.x, near, kSample);
  EXPECT_NEAR(run.ground_a.y, 0.0, 1e-9);
  EXPECT_NEAR(run.image_a.u, k.cx, 1e-6);  // straight ahead: the middle column
  EXPECT_NEAR(run.image_a.v, k.height, 3.0);  // 1 cm on the ground is ~2.7 rows here
  // Far end: the line's end at world y = 3, 5.5 m ahead, inside the image.
  EXPECT_NEAR(run.ground_b.x, 5.5, 1e-9);
  const double below = std::atan(cam.z / (5.5 - cam.x));
  EXPECT_NEAR(run.image_b.v, k.cy + k.fy * std::tan(below - kPitch), 1e-6);
  EXPECT_NEAR(run.image_b.u, k.cx, 1e-6);

  ASSERT_EQ(truth.rings.size(), 1U);
  EXPECT_TRUE(truth.rings[0].visible);
  EXPECT_GT(truth.rings[0].visible_fraction, 0.9);  // 2.5 m ahead: the whole circle fits
  EXPECT_FALSE(truth.ball.present);
  EXPECT_FALSE(truth.lines_truncated);
}

TEST(SimCameraTruth, LineAcrossTheViewIsCutByTheImageSides) {
  World world = test::open_field();
  world.markings.push_back(Marking{{2.0, 3.0}, {2.0, -3.0}, 0.05});  // robot y from +3 to -3 at x = 2
  CameraRenderer r(std::move(world), CameraSpec{}, 1);
  r.render(test::facing_east(), kHead);
  const hal::CameraIntrinsics k = hal::CameraIntrinsics::nao();
  const HandCamera cam;
  // Depth of the ground point (2, y) along the optical axis, the same for every y.
  const double depth = (2.0 - cam.x) * std::cos(kPitch) + cam.z * std::sin(kPitch);
  const double half_width = k.cx * depth / k.fx;  // u = 0 and u = 640 on the ground
  ASSERT_EQ(r.truth().lines.size(), 1U);
  const LineRunTruth& run = r.truth().lines[0];
  EXPECT_NEAR(run.ground_a.x, 2.0, 1e-9);
  EXPECT_NEAR(run.ground_a.y, half_width, kSample);  // end a is on the left: u near 0
  EXPECT_NEAR(run.ground_b.y, -half_width, kSample);
  EXPECT_NEAR(run.image_a.u, 0.0, 4.0);
  EXPECT_NEAR(run.image_b.u, k.width, 4.0);
  EXPECT_NEAR(run.image_a.v, run.image_b.v, 1e-6);  // parallel to the image rows
}

TEST(SimCameraTruth, BallOnTheLineSplitsItAndIsReported) {
  World world = centre_line_world();
  world.rings.clear();
  world.ball = Ball{{0.0, 0.0}, 0.1};  // 2.5 m ahead, on the line
  CameraRenderer r(std::move(world), CameraSpec{}, 1);
  r.render(kOnCentreLine, kHead);
  const FrameTruth& truth = r.truth();
  ASSERT_EQ(truth.lines.size(), 2U);
  EXPECT_LT(truth.lines[0].ground_b.x, 2.5);  // hidden from just under the ball's front
  EXPECT_GT(truth.lines[1].ground_a.x, 2.6);  // to the end of its "shadow" behind it
  EXPECT_GT(truth.lines[1].image_a.v, truth.lines[1].image_b.v);

  const BallTruth& ball = truth.ball;
  const hal::CameraIntrinsics k = hal::CameraIntrinsics::nao();
  const HandCamera cam;
  EXPECT_TRUE(ball.present);
  EXPECT_TRUE(ball.visible);
  EXPECT_DOUBLE_EQ(ball.visible_fraction, 1.0);
  EXPECT_NEAR(ball.position.x, 2.5, 1e-9);
  EXPECT_NEAR(ball.position.y, 0.0, 1e-9);
  // The centre, 0.1 m up, 2.5 m ahead: its depth and image row by hand.
  const double dx = 2.5 - cam.x;
  const double dz = 0.1 - cam.z;
  const double depth = dx * std::cos(kPitch) - dz * std::sin(kPitch);
  const double down = -(dx * std::sin(kPitch) + dz * std::cos(kPitch));  // camera y (down)
  EXPECT_NEAR(ball.image_centre.u, k.cx, 1e-6);
  EXPECT_NEAR(ball.image_centre.v, k.cy + k.fy * down / depth, 1e-6);
  EXPECT_NEAR(ball.image_radius, k.fx * 0.1 / depth, 1e-6);
}

TEST(SimCameraTruth, PartlyHiddenBallHasAFractionBetweenZeroAndOne) {
  World world = test::open_field();
  world.ball = Ball{{2.0, 0.0}, 0.1};
  world.circles.push_back(Circle{{1.0, 0.08}, 0.1, 0.58, ObstacleKind::kRobot});  // covers its left part
  CameraRenderer r(std::move(world), CameraSpec{}, 1);
  r.render(test::facing_east(), kHead);
  EXPECT_TRUE(r.truth().ball.visible);
  EXPECT_GT(r.truth().ball.visible_fraction, 0.05);
  EXPECT_LT(r.truth().ball.visible_fraction, 0.95);
}

TEST(SimCameraTruth, NothingBehindTheCamera) {
  CameraRenderer r(centre_line_world(), CameraSpec{}, 1);
  r.render(hal::Pose2{0.0, -2.5, std::numbers::pi}, kHead);  // looking south, away from the line
  EXPECT_TRUE(r.truth().lines.empty());
  EXPECT_FALSE(r.truth().rings[0].visible);
}

}  // namespace
}  // namespace ringlet::sim_hal
