// Classification of whole frames (YUYV and BGR agree) and the horizon from the head pose.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ringlet/vision/class_image.hpp"
#include "ringlet/vision/horizon.hpp"
#include "synthetic_field.hpp"

namespace ringlet::vision {
namespace {

using testing::Camera;
using testing::render;

TEST(Horizon, PanTiltHorizonIsTheRowOfZeroElevation) {
  Camera cam;
  for (const double pitch : {0.0, 0.2, 0.35, -0.1}) {
    cam.head = {0.4, pitch};
    const auto pose = cam.pose();
    // Hand-computed: a pan-tilt camera has no roll, its horizon is v = cy − fy·tan(pitch).
    const double expected = cam.k.cy - cam.k.fy * std::tan(pitch);
    EXPECT_NEAR(horizon_v(cam.k, pose, 0.0), expected, 1e-9);
    EXPECT_NEAR(horizon_v(cam.k, pose, 639.0), expected, 1e-9);
    std::vector<int> rows(640);
    const int first = horizon_rows(cam.k, pose, 0, rows);
    const int want = std::clamp(static_cast<int>(std::floor(expected - 0.5)) + 1, 0, 480);
    EXPECT_EQ(first, want) << pitch;
    // The first ground row's pixel centre is below the horizon, the row above is not.
    if (first > 0 && first < 480) {
      EXPECT_TRUE(hal::pixel_to_ground(cam.k, pose, {320.5, first + 0.5}).has_value());
      EXPECT_FALSE(hal::pixel_to_ground(cam.k, pose, {320.5, first - 0.5}).has_value());
    }
    EXPECT_EQ(horizon_rows(cam.k, pose, 3, rows), std::min(want + 3, 480));
  }
}

TEST(Horizon, LookingUpHasNoGround) {
  Camera cam;
  cam.head = {0.0, -0.6};  // 34° up with a 22° half field of view: sky only
  std::vector<int> rows(640);
  EXPECT_EQ(horizon_rows(cam.k, cam.pose(), 0, rows), 480);
}

TEST(Classify, YuyvAndBgrAgree) {
  const ColourTable table = ColourTable::from_thresholds({});
  Camera cam;
  auto scene = testing::field_scene();
  scene.noise = 0;
  const auto bgr = render(scene, cam, hal::PixelFormat::kBgr8);
  const auto yuyv = render(scene, cam, hal::PixelFormat::kYuyv);
  ClassImage a(640, 480), b(640, 480);
  ASSERT_TRUE(a.classify(bgr.view, table, 0, 1));
  ASSERT_TRUE(b.classify(yuyv.view, table, 0, 1));
  int compared = 0, mixed_pairs = 0;
  for (int y = 0; y < 480; ++y) {
    for (int x = 0; x < 640; x += 2) {
      const std::uint8_t* p = bgr.bytes.data() + (static_cast<std::size_t>(y) * 640 + static_cast<std::size_t>(x)) * 3;
      if (!std::equal(p, p + 3, p + 3)) {  // the pair straddles a colour edge: YUYV shares chroma
        ++mixed_pairs;
        continue;
      }
      compared += 2;
      ASSERT_EQ(a.at(x, y), b.at(x, y)) << x << "," << y;
      ASSERT_EQ(a.at(x + 1, y), b.at(x + 1, y)) << x + 1 << "," << y;
    }
  }
  EXPECT_GT(compared, 290000);
  EXPECT_LT(mixed_pairs, 5000);
  // And the picture is what the scene says: wall on top, field below, ball pixels exist.
  EXPECT_EQ(a.at(320, 2), ColourClass::kOther);
  EXPECT_EQ(a.at(5, 470), ColourClass::kField);
  int ball = 0, line = 0;
  for (int y = 0; y < 480; ++y)
    for (int x = 0; x < 640; ++x) {
      ball += a.at(x, y) == ColourClass::kBall;
      line += a.at(x, y) == ColourClass::kLine;
    }
  EXPECT_GT(ball, 100);
  EXPECT_GT(line, 1000);
}

TEST(Classify, StepTwoAndFirstRowTouchOnlyTheGrid) {
  const ColourTable table = ColourTable::from_thresholds({});
  Camera cam;
  const auto f = render(testing::field_scene(), cam, hal::PixelFormat::kYuyv);
  ClassImage full(640, 480), half(640, 480);
  ASSERT_TRUE(full.classify(f.view, table, 101, 1));
  ASSERT_TRUE(half.classify(f.view, table, 101, 2));
  EXPECT_EQ(half.first_row(), 101);
  EXPECT_EQ(half.step(), 2);
  EXPECT_TRUE(half.sampled(0, 101));
  EXPECT_FALSE(half.sampled(1, 101));
  EXPECT_FALSE(half.sampled(0, 102));
  EXPECT_FALSE(half.sampled(0, 99));
  for (int y = 101; y < 480; y += 2)
    for (int x = 0; x < 640; x += 2) ASSERT_EQ(full.at(x, y), half.at(x, y));
}

TEST(Classify, RefusesAFrameOfTheWrongSize) {
  const ColourTable table;
  Camera cam;
  const auto f = render({}, cam, hal::PixelFormat::kBgr8);
  ClassImage small(320, 240);
  EXPECT_FALSE(small.classify(f.view, table, 0, 1));
}

}  // namespace
}  // namespace ringlet::vision
