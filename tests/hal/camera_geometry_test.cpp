// The head camera's geometry against hand-computed cases: projection, its inverse onto the ground,
// head yaw and pitch, the mount offsets, the horizon; the torso's tilt in the chain.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ringlet/hal/camera_geometry.hpp"

namespace ringlet::hal {
namespace {

constexpr double kPi = std::numbers::pi;

// A camera exactly at the pivot, 0.5 m above the ground.
constexpr CameraMount kBare{0.5, 0.0, 0.0};

TEST(CameraIntrinsics, NaoFieldOfView) {
  const auto k = CameraIntrinsics::nao();
  EXPECT_EQ(k.width, 640);
  EXPECT_EQ(k.height, 480);
  EXPECT_DOUBLE_EQ(k.cx, 320.0);
  EXPECT_DOUBLE_EQ(k.cy, 240.0);
  EXPECT_NEAR(k.fx, 320.0 / std::tan(deg_to_rad(28.5)), 1e-9);  // ~589.3
  EXPECT_NEAR(k.fy, 240.0 / std::tan(deg_to_rad(22.0)), 1e-9);  // ~594.0
}

TEST(CameraGeometry, LevelCameraProjectsGroundPointsBelowTheCentre) {
  const auto k = CameraIntrinsics::nao();
  const auto pose = CameraPose::from_head(kBare, {0.0, 0.0});
  // 2 m ahead on the ground: 0.5 m below the axis at depth 2.
  const auto ahead = project(k, pose, {2.0, 0.0, 0.0});
  ASSERT_TRUE(ahead);
  EXPECT_NEAR(ahead->u, 320.0, 1e-9);
  EXPECT_NEAR(ahead->v, 240.0 + k.fy * 0.25, 1e-9);
  // 1 m to the left: left of the centre column.
  const auto left = project(k, pose, {2.0, 1.0, 0.0});
  ASSERT_TRUE(left);
  EXPECT_NEAR(left->u, 320.0 - k.fx * 0.5, 1e-9);
  // Behind the camera: no pixel.
  EXPECT_FALSE(project(k, pose, {-1.0, 0.0, 0.0}));
}

TEST(CameraGeometry, PixelToGroundInvertsProjection) {
  const auto k = CameraIntrinsics::nao();
  const CameraMount mount{};  // with the default offsets
  const auto pose = CameraPose::from_head(mount, {0.3, 0.4});
  for (const RobotPoint p : {RobotPoint{1.0, 0.2}, RobotPoint{2.5, 1.5}, RobotPoint{0.7, 0.5}}) {
    const auto px = project(k, pose, {p.x, p.y, 0.0});
    ASSERT_TRUE(px);
    const auto back = pixel_to_ground(k, pose, *px);
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->x, p.x, 1e-9);
    EXPECT_NEAR(back->y, p.y, 1e-9);
  }
}

TEST(CameraGeometry, PositivePitchLooksDown) {
  const auto k = CameraIntrinsics::nao();
  const CameraMount mount{0.45, 0.05, 0.06};
  // Straight down: the head's x axis points at the ground, its z axis forward, so the camera sits
  // 0.06 m ahead of the pivot and 0.05 m below it, and the centre pixel sees the ground under it.
  const auto pose = CameraPose::from_head(mount, {0.0, kPi / 2.0});
  EXPECT_NEAR(pose.position.x, 0.06, 1e-12);
  EXPECT_NEAR(pose.position.z, 0.40, 1e-12);
  const auto centre = pixel_to_ground(k, pose, {320.0, 240.0});
  ASSERT_TRUE(centre);
  EXPECT_NEAR(centre->x, 0.06, 1e-12);
  EXPECT_NEAR(centre->y, 0.0, 1e-12);
  // Image up is robot ahead when looking down: a row above the centre sees further ahead.
  const auto above = pixel_to_ground(k, pose, {320.0, 140.0});
  ASSERT_TRUE(above);
  EXPECT_NEAR(above->x, 0.06 + 0.40 * 100.0 / k.fy, 1e-12);
}

TEST(CameraGeometry, YawLeftLooksLeft) {
  const auto k = CameraIntrinsics::nao();
  const auto pose = CameraPose::from_head(kBare, {kPi / 2.0, 0.0});
  const auto px = project(k, pose, {0.0, 2.0, 0.0});  // 2 m to the left
  ASSERT_TRUE(px);
  EXPECT_NEAR(px->u, 320.0, 1e-9);
  EXPECT_NEAR(px->v, 240.0 + k.fy * 0.25, 1e-9);
}

TEST(CameraGeometry, AxesFormARotationThatToCameraInverts) {
  const CameraMount mount{};
  for (const HeadJoints head : {HeadJoints{0.0, 0.0}, HeadJoints{0.7, -0.3}, HeadJoints{-1.9, 0.5}}) {
    const auto pose = CameraPose::from_head(mount, head);
    const auto& a = pose.axes;
    const auto dot = [](const Vec3& p, const Vec3& q) { return p.x * q.x + p.y * q.y + p.z * q.z; };
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t j = 0; j < 3; ++j) EXPECT_NEAR(dot(a[i], a[j]), i == j ? 1.0 : 0.0, 1e-14);
    }
    // Right-handed: right × down = forward (OpenCV's camera frame).
    const Vec3 cross{a[0].y * a[1].z - a[0].z * a[1].y, a[0].z * a[1].x - a[0].x * a[1].z,
                     a[0].x * a[1].y - a[0].y * a[1].x};
    EXPECT_NEAR(cross.x, a[2].x, 1e-14);
    EXPECT_NEAR(cross.y, a[2].y, 1e-14);
    EXPECT_NEAR(cross.z, a[2].z, 1e-14);
    // A point one metre along each camera axis from the camera is that unit vector in camera
    // coordinates, and the direction maps back.
    for (std::size_t i = 0; i < 3; ++i) {
      const Vec3 p{pose.position.x + a[i].x, pose.position.y + a[i].y, pose.position.z + a[i].z};
      const Vec3 c = pose.to_camera(p);
      EXPECT_NEAR(c.x, i == 0 ? 1.0 : 0.0, 1e-14);
      EXPECT_NEAR(c.y, i == 1 ? 1.0 : 0.0, 1e-14);
      EXPECT_NEAR(c.z, i == 2 ? 1.0 : 0.0, 1e-14);
      const Vec3 back = pose.to_robot_direction(c);
      EXPECT_NEAR(back.x, a[i].x, 1e-14);
      EXPECT_NEAR(back.y, a[i].y, 1e-14);
      EXPECT_NEAR(back.z, a[i].z, 1e-14);
    }
  }
}

TEST(CameraGeometry, NothingAtOrAboveTheHorizonMeetsTheGround) {
  const auto k = CameraIntrinsics::nao();
  const auto pose = CameraPose::from_head(kBare, {0.0, 0.0});
  EXPECT_FALSE(pixel_to_ground(k, pose, {320.0, 240.0}));  // the optical axis is level
  EXPECT_FALSE(pixel_to_ground(k, pose, {100.0, 10.0}));   // above it
  EXPECT_TRUE(pixel_to_ground(k, pose, {100.0, 300.0}));
}

// ---- the torso's tilt (hal::BodyTilt) --------------------------------------------------------

double dot(const Vec3& p, const Vec3& q) { return p.x * q.x + p.y * q.y + p.z * q.z; }

TEST(CameraGeometryBody, UprightBodyIsFromHeadBitForBit) {
  const CameraMount mount{};
  const HeadJoints head{0.4, 0.3};
  const auto a = CameraPose::from_head(mount, head);
  const auto b = CameraPose::from_body(mount, BodyTilt{0.0, 0.0}, head);
  EXPECT_EQ(a.position.x, b.position.x);
  EXPECT_EQ(a.position.y, b.position.y);
  EXPECT_EQ(a.position.z, b.position.z);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(a.axes[i].x, b.axes[i].x);
    EXPECT_EQ(a.axes[i].y, b.axes[i].y);
    EXPECT_EQ(a.axes[i].z, b.axes[i].z);
  }
}

// Leaning forward by 5° with the head straight ahead turns the camera exactly as 5° more head
// pitch does; only the pivot moves (forward and down, on a circle about the ground point).
TEST(CameraGeometryBody, BodyPitchAddsToHeadPitchWhenYawIsZero) {
  const CameraMount mount{};
  const double lean = deg_to_rad(5.0);
  const auto tilted = CameraPose::from_body(mount, {lean, 0.0}, {0.0, 0.2});
  const auto more_head = CameraPose::from_head(mount, {0.0, 0.2 + lean});
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(tilted.axes[i].x, more_head.axes[i].x, 1e-15);
    EXPECT_NEAR(tilted.axes[i].y, more_head.axes[i].y, 1e-15);
    EXPECT_NEAR(tilted.axes[i].z, more_head.axes[i].z, 1e-15);
  }
  // The camera position is the upright one turned by 5° about the y axis through the origin.
  const auto upright = CameraPose::from_head(mount, {0.0, 0.2});
  const double c = std::cos(lean), s = std::sin(lean);
  EXPECT_NEAR(tilted.position.x, c * upright.position.x + s * upright.position.z, 1e-15);
  EXPECT_NEAR(tilted.position.y, 0.0, 1e-15);
  EXPECT_NEAR(tilted.position.z, -s * upright.position.x + c * upright.position.z, 1e-15);
  // Leaning forward brings the camera forward and (slightly) down.
  EXPECT_GT(tilted.position.x, upright.position.x);
  EXPECT_LT(tilted.position.z, upright.position.z);
}

// Positive roll leans the torso to its right: a camera at the pivot moves to the right (−y) and
// its right axis dips by the roll angle, while the optical axis stays level and straight ahead.
TEST(CameraGeometryBody, RollLeansToTheRightAndTurnsTheCameraAboutItsAxis) {
  const double roll = deg_to_rad(10.0);
  const auto pose = CameraPose::from_body(kBare, {0.0, roll}, {0.0, 0.0});
  EXPECT_NEAR(pose.position.y, -0.5 * std::sin(roll), 1e-15);
  EXPECT_NEAR(pose.position.z, 0.5 * std::cos(roll), 1e-15);
  // The camera's right axis points down at the roll angle.
  EXPECT_NEAR(pose.axes[0].z, -std::sin(roll), 1e-15);
  // The optical axis stays level and straight ahead.
  EXPECT_NEAR(pose.axes[2].x, 1.0, 1e-15);
  EXPECT_NEAR(pose.axes[2].z, 0.0, 1e-15);
}

// Pixel → ground → pixel is the identity with any tilt, and the ground point really lies on the
// viewing ray (checked against the upright camera, which is another route to the same world).
TEST(CameraGeometryBody, PixelToGroundRoundTripWithTilt) {
  const auto k = CameraIntrinsics::nao();
  const CameraMount mount{};
  for (const BodyTilt body : {BodyTilt{deg_to_rad(7.0), 0.0}, BodyTilt{0.0, deg_to_rad(-6.0)},
                              BodyTilt{deg_to_rad(-4.0), deg_to_rad(3.0)}}) {
    for (const HeadJoints head : {HeadJoints{0.0, 0.35}, HeadJoints{0.6, 0.2}, HeadJoints{-0.9, 0.45}}) {
      const auto pose = CameraPose::from_body(mount, body, head);
      for (const Pixel px : {Pixel{320.5, 400.5}, Pixel{10.5, 470.5}, Pixel{630.5, 300.5}}) {
        const auto g = pixel_to_ground(k, pose, px);
        ASSERT_TRUE(g) << body.pitch << " " << body.roll << " " << head.yaw << " " << head.pitch;
        const auto back = project(k, pose, {g->x, g->y, 0.0});
        ASSERT_TRUE(back);
        EXPECT_NEAR(back->u, px.u, 1e-8);
        EXPECT_NEAR(back->v, px.v, 1e-8);
      }
    }
  }
}

// A ground point seen by a tilted robot: its distance differs from what the upright model says,
// which is the whole point (5° of lean at 2 m is about 0.5 m of error).
TEST(CameraGeometryBody, IgnoringTheLeanMisplacesGroundPoints) {
  const auto k = CameraIntrinsics::nao();
  const CameraMount mount{};
  const HeadJoints head{0.0, 0.3};
  const auto tilted = CameraPose::from_body(mount, {deg_to_rad(5.0), 0.0}, head);
  const Vec3 truth{2.0, 0.0, 0.0};
  const auto px = project(k, tilted, truth);
  ASSERT_TRUE(px);
  const auto seen = pixel_to_ground(k, tilted, *px);
  ASSERT_TRUE(seen);
  EXPECT_NEAR(seen->x, 2.0, 1e-9);
  const auto naive = pixel_to_ground(k, CameraPose::from_head(mount, head), *px);
  ASSERT_TRUE(naive);
  EXPECT_GT(naive->x - 2.0, 0.3);  // the upright model puts it much further away
}

TEST(CameraGeometryBody, TiltedAxesStayARightHandedRotation) {
  for (const BodyTilt body : {BodyTilt{0.3, -0.2}, BodyTilt{-0.5, 0.35}}) {
    const auto pose = CameraPose::from_body(CameraMount{}, body, {0.7, -0.3});
    const auto& a = pose.axes;
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t j = 0; j < 3; ++j) EXPECT_NEAR(dot(a[i], a[j]), i == j ? 1.0 : 0.0, 1e-14);
    }
    const Vec3 cross{a[0].y * a[1].z - a[0].z * a[1].y, a[0].z * a[1].x - a[0].x * a[1].z,
                     a[0].x * a[1].y - a[0].y * a[1].x};
    EXPECT_NEAR(cross.x, a[2].x, 1e-14);
    EXPECT_NEAR(cross.y, a[2].y, 1e-14);
    EXPECT_NEAR(cross.z, a[2].z, 1e-14);
  }
}

TEST(InertialState, InvalidReadingMeansUpright) {
  InertialState imu;
  imu.tilt = {0.1, 0.2};
  EXPECT_EQ(imu.tilt_or_upright().pitch, 0.0);
  imu.valid = true;
  EXPECT_EQ(imu.tilt_or_upright().pitch, 0.1);
  EXPECT_EQ(imu.tilt_or_upright().roll, 0.2);
}

// A camera mounted pitched looks where more head pitch would, but turns in place: the pivot's
// offset does not swing with it. 0 is the nominal mount, bit for bit.
TEST(CameraGeometry, AMountedPitchTurnsTheCameraInPlace) {
  const CameraMount nominal{};
  CameraMount pitched = nominal;
  pitched.pitch = deg_to_rad(2.5);
  const HeadJoints head{0.3, 0.2};
  const CameraPose a = CameraPose::from_head(pitched, head);
  const CameraPose more_head = CameraPose::from_head(nominal, {head.yaw, head.pitch + pitched.pitch});
  const CameraPose as_mounted = CameraPose::from_head(nominal, head);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(a.axes[i].x, more_head.axes[i].x, 1e-12);
    EXPECT_NEAR(a.axes[i].y, more_head.axes[i].y, 1e-12);
    EXPECT_NEAR(a.axes[i].z, more_head.axes[i].z, 1e-12);
  }
  EXPECT_EQ(a.position.x, as_mounted.position.x);
  EXPECT_EQ(a.position.y, as_mounted.position.y);
  EXPECT_EQ(a.position.z, as_mounted.position.z);
  EXPECT_NE(a.position.x, more_head.position.x);  // more head pitch swings the camera about the pivot
  CameraMount zero = nominal;
  zero.pitch = 0.0;
  const CameraPose z = CameraPose::from_head(zero, head);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(z.axes[i].x, as_mounted.axes[i].x);
}

}  // namespace
}  // namespace ringlet::hal
