// The rendered picture: what known pixels show (carpet, paint, background, floor, obstacles, the
// ball), who hides whom, YUYV against BGR, and that a seed always gives the same bytes.
#include <gtest/gtest.h>

#include <vector>

#include "camera_test_support.hpp"
#include "ringlet/sim_hal/camera_renderer.hpp"
#include "ringlet/hal/yuv.hpp"
#include "sim_test_support.hpp"

namespace ringlet::sim_hal {
namespace {

using test::bgr_at;
using test::label_at;
using test::pixel_of;

const hal::HeadJoints kLookDown{0.0, 0.3};  // the top ~55 rows are above the horizon

World field_with_line() {
  World world = test::open_field();
  world.markings.push_back(Marking{{2.0, -1.0}, {2.0, 1.0}, 0.1});  // across the view, 2 m ahead
  return world;
}

bool whitish(test::Bgr c) { return c.b > 170 && c.g > 170 && c.r > 170; }
bool greenish(test::Bgr c) { return c.g > c.r + 40 && c.g > c.b + 40; }

TEST(SimCameraRenderer, PaintIsWhiteCarpetIsGreenAboveTheHorizonIsBackground) {
  CameraRenderer r(field_with_line(), CameraSpec{}, 1);
  r.render(test::facing_east(), kLookDown);
  const CameraSpec& spec = r.spec();

  const auto line = pixel_of(spec, kLookDown, {2.0, 0.0, 0.0});
  EXPECT_EQ(label_at(r, line), PixelLabel::kMarking);
  EXPECT_TRUE(whitish(bgr_at(r, line)));

  const auto carpet = pixel_of(spec, kLookDown, {1.5, 0.5, 0.0});
  EXPECT_EQ(label_at(r, carpet), PixelLabel::kCarpet);
  EXPECT_TRUE(greenish(bgr_at(r, carpet)));

  const test::PixelIndex sky{320, 10};
  EXPECT_EQ(label_at(r, sky), PixelLabel::kBackground);
  const test::Bgr bg = bgr_at(r, sky);
  EXPECT_FALSE(greenish(bg));
  EXPECT_FALSE(whitish(bg));

  // The carpet ends at the bounds (x = 5): beyond it, still below the horizon, is the hall floor.
  const auto floor = pixel_of(spec, kLookDown, {8.0, 0.0, 0.0});
  EXPECT_EQ(label_at(r, floor), PixelLabel::kFloor);
}

TEST(SimCameraRenderer, ObstacleHidesTheLineBehindIt) {
  World world = field_with_line();
  world.circles.push_back(Circle{{1.0, 0.0}, 0.15, 0.58, ObstacleKind::kRobot});
  CameraRenderer r(std::move(world), CameraSpec{}, 1);
  r.render(test::facing_east(), kLookDown);
  EXPECT_EQ(label_at(r, pixel_of(r.spec(), kLookDown, {2.0, 0.0, 0.0})), PixelLabel::kRobot);
  // The line still shows beside the robot.
  EXPECT_EQ(label_at(r, pixel_of(r.spec(), kLookDown, {2.0, 0.6, 0.0})), PixelLabel::kMarking);
}

TEST(SimCameraRenderer, BallIsOrangeAndRobotInFrontHidesIt) {
  World world = test::open_field();
  world.ball = Ball{{1.5, 0.3}, 0.05};
  {
    CameraRenderer r(world, CameraSpec{}, 1);
    r.render(test::facing_east(), kLookDown);
    const auto centre = pixel_of(r.spec(), kLookDown, {1.5, 0.3, 0.05});
    EXPECT_EQ(label_at(r, centre), PixelLabel::kBall);
    const test::Bgr c = bgr_at(r, centre);
    EXPECT_GT(c.r, c.g);
    EXPECT_GT(c.g, c.b);
    EXPECT_GT(c.r, 150);
    EXPECT_TRUE(r.truth().ball.visible);
    EXPECT_DOUBLE_EQ(r.truth().ball.visible_fraction, 1.0);
  }
  world.circles.push_back(Circle{{0.8, 0.16}, 0.15, 0.58, ObstacleKind::kRobot});
  CameraRenderer r(world, CameraSpec{}, 1);
  r.render(test::facing_east(), kLookDown);
  EXPECT_EQ(label_at(r, pixel_of(r.spec(), kLookDown, {1.5, 0.3, 0.05})), PixelLabel::kRobot);
  EXPECT_FALSE(r.truth().ball.visible);
  EXPECT_EQ(r.truth().ball.visible_fraction, 0.0);
}

TEST(SimCameraRenderer, PostIsSeenAgainstTheBackground) {
  World world = test::open_field();
  world.circles.push_back(Circle{{3.0, 0.0}, 0.05, 0.8, ObstacleKind::kPost});
  CameraRenderer r(std::move(world), CameraSpec{}, 1);
  r.render(test::facing_east(), kLookDown);
  // The post's top part, above the horizon from a 0.5 m high camera.
  const auto top = pixel_of(r.spec(), kLookDown, {3.0, 0.0, 0.65});
  EXPECT_EQ(label_at(r, top), PixelLabel::kPost);
  EXPECT_TRUE(whitish(bgr_at(r, top)));
}

TEST(SimCameraRenderer, SunStripesMakeBrightAndShadowBands) {
  World world = test::open_field();
  world.lighting.texture = 0.0;
  world.lighting.sun_strength = 0.4;
  world.lighting.sun_period = 2.0;
  world.lighting.sun_angle = 0.0;  // stripes run north; x decides the band: [0, 1) bright, [1, 2) shadow
  CameraRenderer r(std::move(world), CameraSpec{}, 1);
  r.render(test::facing_east(), kLookDown);
  const test::Bgr bright = bgr_at(r, pixel_of(r.spec(), kLookDown, {2.5, 0.0, 0.0}));
  const test::Bgr shadow = bgr_at(r, pixel_of(r.spec(), kLookDown, {1.5, 0.0, 0.0}));
  EXPECT_GT(bright.g, shadow.g * 2);  // 1.4 against 0.6
}

TEST(SimCameraRenderer, YuyvIsTheSharedConversionOfTheBgrPicture) {
  World world = field_with_line();
  world.ball = Ball{{1.5, 0.3}, 0.05};
  CameraRenderer r(std::move(world), CameraSpec{}, 3);
  r.render(test::facing_east(), kLookDown);
  std::vector<std::uint8_t> yuyv(640U * 480U * 2U);
  hal::bgr_to_yuyv(r.bgr(), 640, 480, yuyv);
  const auto bgr = r.bgr();
  for (std::size_t pair = 0; pair < 640U * 480U / 2U; ++pair) {
    const std::uint8_t* p = &bgr[pair * 6];
    const hal::Yuv a = hal::bgr_to_yuv(p[0], p[1], p[2]);
    const hal::Yuv b = hal::bgr_to_yuv(p[3], p[4], p[5]);
    ASSERT_EQ(yuyv[pair * 4], a.y) << pair;
    ASSERT_EQ(yuyv[pair * 4 + 2], b.y) << pair;
    ASSERT_NEAR(yuyv[pair * 4 + 1], (a.u + b.u) / 2.0, 0.5) << pair;
    ASSERT_NEAR(yuyv[pair * 4 + 3], (a.v + b.v) / 2.0, 0.5) << pair;
  }
}

std::uint64_t picture_hash(const CameraRenderer& r) {
  test::Fnv1a h;
  h.bytes(r.bgr().data(), r.bgr().size());
  return h.result();
}

TEST(SimCameraRenderer, SameSeedSameBytesOtherSeedOtherTexture) {
  const World world = load_world(RINGLET_SIM_WORLDS_DIR "/spl_field.world");
  const hal::Pose2 pose{-2.0, -0.4, 1.4};
  const hal::HeadJoints head{0.1, 0.3};
  CameraRenderer a(world, CameraSpec{}, 5);
  CameraRenderer b(world, CameraSpec{}, 5);
  CameraRenderer c(world, CameraSpec{}, 6);
  a.render(pose, head);
  b.render(pose, head);
  c.render(pose, head);
  EXPECT_EQ(picture_hash(a), picture_hash(b));
  EXPECT_NE(picture_hash(a), picture_hash(c));
  // Rendering again gives the same bytes: what earlier frames showed does not matter, only how
  // many there were (the SPL look's sensor noise and exposure drift follow the frame count).
  a.render(hal::Pose2{1.0, 1.0, 0.0}, hal::HeadJoints{});
  a.render(pose, head);
  b.render(pose, head);
  b.render(pose, head);
  EXPECT_EQ(picture_hash(a), picture_hash(b));
}

}  // namespace
}  // namespace ringlet::sim_hal
