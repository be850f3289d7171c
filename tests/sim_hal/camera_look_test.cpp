// The SPL look (camera_look.hpp): the black-and-white ball, NAO-shaped robots, the camera's
// drift, noise and blur, and above all that the randomized looks ringlet-dataset draws cover the
// colour ranges measured on real NAO photos of SPL fields (issue 10, full-range BT.601): carpet V
// medians 112..128, line U down to 95..103, backlit line Y 157..168. Measured on rendered frames,
// with the renderer's own per-pixel labels saying which pixels are carpet and which are line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "camera_test_support.hpp"
#include "ringlet/hal/yuv.hpp"
#include "ringlet/sim_hal/camera_renderer.hpp"
#include "ringlet/sim_hal/look_randomizer.hpp"

namespace ringlet::sim_hal {
namespace {

using test::label_at;
using test::pixel_of;

World spl_world() { return load_world(RINGLET_SIM_WORLDS_DIR "/spl_field.world"); }

/// A quarter-size NAO camera: the colour statistics do not need 640×480, the test's time does.
CameraSpec small_camera() {
  CameraSpec spec;
  spec.intrinsics = hal::CameraIntrinsics::from_fov(320, 240, 57.0, 44.0);
  return spec;
}

struct Stats {
  int carpet_v = -1;  // medians over the frame's pixels of each kind; -1 when none
  int line_u = -1;
  int line_y = -1;
};

int median(std::vector<int>& values) {
  if (values.empty()) return -1;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2), values.end());
  return values[values.size() / 2];
}

/// Medians of carpet V and of line U and Y. Line pixels count only with line pixels on all four
/// sides, so their colour is the paint's, not a blend with the carpet.
Stats measure(const CameraRenderer& r) {
  const int w = r.spec().intrinsics.width;
  const int h = r.spec().intrinsics.height;
  const auto labels = r.labels();
  const auto bgr = r.bgr();
  std::vector<int> carpet_v, line_u, line_y;
  for (int v = 1; v + 1 < h; ++v) {
    for (int u = 1; u + 1 < w; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * static_cast<std::size_t>(w) + static_cast<std::size_t>(u);
      const hal::Yuv c = hal::bgr_to_yuv(bgr[3 * i], bgr[3 * i + 1], bgr[3 * i + 2]);
      if (labels[i] == PixelLabel::kCarpet) carpet_v.push_back(c.v);
      const auto is_line = [&](std::size_t j) { return labels[j] == PixelLabel::kMarking; };
      if (is_line(i) && is_line(i - 1) && is_line(i + 1) && is_line(i - static_cast<std::size_t>(w)) &&
          is_line(i + static_cast<std::size_t>(w))) {
        line_u.push_back(c.u);
        line_y.push_back(c.y);
      }
    }
  }
  return {median(carpet_v), median(line_u), median(line_y)};
}

/// Views of the centre line and circle and of a penalty area, from near and far.
constexpr std::array<hal::Pose2, 4> kViews{{{-1.6, 0.2, 1.5708}, {-2.0, -1.5, 1.2}, {2.0, 0.5, 1.5708}, {0.6, -2.4, 0.3}}};

TEST(SimCameraLook, RandomizedLooksCoverTheRealFieldsColourRanges) {
  const World base = spl_world();
  std::vector<int> carpet_v, line_u, backlit_line_y;
  int frames = 0;
  for (std::uint64_t seed = 1; seed <= 160; ++seed) {
    World world = base;
    const LookDraw draw = draw_spl_look(world.lighting, BallLook::kBlackWhite, seed);
    world.look = draw.look;
    world.lighting = draw.lighting;
    CameraRenderer r(std::move(world), small_camera(), seed);
    r.render(kViews[seed % kViews.size()], hal::HeadJoints{0.0, 0.42});
    const Stats s = measure(r);
    ASSERT_GE(s.carpet_v, 0) << "seed " << seed << ": no carpet in view";
    ++frames;
    carpet_v.push_back(s.carpet_v);
    if (s.line_u >= 0) line_u.push_back(s.line_u);
    if (draw.look.light == LightKind::kBacklight && s.line_y >= 0) backlit_line_y.push_back(s.line_y);
  }
  ASSERT_EQ(frames, 160);
  ASSERT_GE(line_u.size(), 100U) << "too few frames show a line";
  ASSERT_GE(backlit_line_y.size(), 10U) << "too few backlit frames show a line";

  // Carpet V medians span at least the real 112..128, and most frames lie inside it.
  const auto [v_min, v_max] = std::minmax_element(carpet_v.begin(), carpet_v.end());
  const auto [u_lo, u_hi] = std::minmax_element(line_u.begin(), line_u.end());
  const auto [y_lo, y_hi] = std::minmax_element(backlit_line_y.begin(), backlit_line_y.end());
  std::printf("carpet V medians %d..%d over %zu frames; line U medians %d..%d over %zu; backlit line Y %d..%d over %zu\n",
              *v_min, *v_max, carpet_v.size(), *u_lo, *u_hi, line_u.size(), *y_lo, *y_hi, backlit_line_y.size());
  EXPECT_LE(*v_min, 112);
  EXPECT_GE(*v_max, 128);
  const auto v_inside = std::count_if(carpet_v.begin(), carpet_v.end(), [](int v) { return v >= 112 && v <= 128; });
  EXPECT_GE(v_inside * 2, static_cast<std::ptrdiff_t>(carpet_v.size())) << "most carpets should look like real ones";

  // Lines: bluish-yellowish white round U 128, but under warm light down into the real 95..103.
  const auto u_real = std::count_if(line_u.begin(), line_u.end(), [](int u) { return u >= 95 && u <= 103; });
  EXPECT_GE(u_real, 5) << "line U should reach the real 95..103 in several frames";
  const auto u_nominal = std::count_if(line_u.begin(), line_u.end(), [](int u) { return u >= 120 && u <= 136; });
  EXPECT_GE(u_nominal, 20) << "and stay near neutral in many";

  // Backlit lines: luminance 157..168 as in the real backlit photo, and both sides of it.
  const auto y_real = std::count_if(backlit_line_y.begin(), backlit_line_y.end(), [](int y) { return y >= 157 && y <= 168; });
  EXPECT_GE(y_real, 3) << "backlit line Y should land in the real 157..168";
  const auto [y_min, y_max] = std::minmax_element(backlit_line_y.begin(), backlit_line_y.end());
  EXPECT_LE(*y_min, 157);
  EXPECT_GE(*y_max, 168);
}

TEST(SimCameraLook, NominalSplLookHasARealCarpet) {
  World world = spl_world();
  world.look = CameraLook{};
  world.look.style = LookStyle::kSpl;
  world.lighting.sun_strength = 0.0;
  CameraRenderer r(std::move(world), small_camera(), 3);
  r.render(kViews[0], hal::HeadJoints{0.0, 0.42});
  const Stats s = measure(r);
  EXPECT_GE(s.carpet_v, 112);
  EXPECT_LE(s.carpet_v, 124);
  EXPECT_GE(s.line_y, 200) << "under even light at exposure 1 the lines are bright";
}

const hal::HeadJoints kLookDown{0.0, 0.3};

World ball_world(BallLook ball) {
  World world = test::open_field();
  world.look.style = LookStyle::kSpl;
  world.look.ball = ball;
  world.look.noise = 0.0;
  world.ball = Ball{{0.7, 0.0}, 0.05};
  return world;
}

TEST(SimCameraLook, TheSplBallIsWhiteWithBlackPatches) {
  CameraRenderer r(ball_world(BallLook::kBlackWhite), CameraSpec{}, 1);
  r.render(test::facing_east(), kLookDown);
  const BallTruth& b = r.truth().ball;
  ASSERT_TRUE(b.visible);
  int dark = 0, bright = 0, coloured = 0, total = 0;
  const auto bgr = r.bgr();
  for (std::size_t i = 0; i < r.labels().size(); ++i) {
    if (r.labels()[i] != PixelLabel::kBall) continue;
    ++total;
    const hal::Yuv c = hal::bgr_to_yuv(bgr[3 * i], bgr[3 * i + 1], bgr[3 * i + 2]);
    if (c.y < 70) ++dark;
    if (c.y > 130) ++bright;
    if (std::abs(c.u - 128) > 20 || std::abs(c.v - 128) > 20) ++coloured;
  }
  ASSERT_GT(total, 500);
  EXPECT_GT(dark, total / 10) << "black pentagons";
  EXPECT_GT(bright, total / 2) << "mostly white";
  EXPECT_LT(coloured, total / 20) << "no colour";
  // The ball's pixel box holds its projected disc's centre and is about its diameter wide.
  EXPECT_LE(b.pixels.u0, b.image_centre.u);
  EXPECT_GE(b.pixels.u1, b.image_centre.u);
  EXPECT_NEAR(b.pixels.u1 - b.pixels.u0, 2.0 * b.image_radius, 3.0);
  EXPECT_NEAR(b.distance, 0.7, 1e-9);
  EXPECT_NEAR(b.bearing, 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(b.in_image_fraction, 1.0);
}

TEST(SimCameraLook, TheOrangeBallStaysAnOption) {
  CameraRenderer r(ball_world(BallLook::kOrange), CameraSpec{}, 1);
  r.render(test::facing_east(), kLookDown);
  const auto centre = pixel_of(r.spec(), kLookDown, {0.7, 0.0, 0.05});
  ASSERT_EQ(label_at(r, centre), PixelLabel::kBall);
  const test::Bgr c = test::bgr_at(r, centre);
  EXPECT_GT(c.r, c.g + 40);
  EXPECT_GT(c.g, c.b + 40);
}

TEST(SimCameraLook, RobotsAreNaoShapedWithRealProportions) {
  World world = test::open_field();
  world.look.style = LookStyle::kSpl;
  world.circles.push_back(Circle{{2.0, 0.3}, 0.15, 0.574, ObstacleKind::kRobot});
  CameraRenderer r(std::move(world), CameraSpec{}, 5);
  r.render(test::facing_east(), hal::HeadJoints{0.0, 0.1});
  ASSERT_EQ(r.truth().robots.size(), 1U);
  const RobotTruth& t = r.truth().robots[0];
  ASSERT_TRUE(t.visible);
  EXPECT_DOUBLE_EQ(t.visible_fraction, 1.0);
  EXPECT_NEAR(t.distance, std::hypot(2.0, 0.3), 1e-9);
  EXPECT_NEAR(t.bearing, std::atan2(0.3, 2.0), 1e-9);
  // Tall and narrow: 0.574 m high, at most 0.31 m across whichever way it faces (arms and feet).
  const double w = t.pixels.u1 - t.pixels.u0;
  const double h = t.pixels.v1 - t.pixels.v0;
  const double fx = r.spec().intrinsics.fx;
  EXPECT_NEAR(h, fx * 0.574 / 2.0, fx * 0.574 / 2.0 * 0.12);
  EXPECT_GT(w, fx * 0.12 / 2.0);
  EXPECT_LT(w, fx * 0.32 / 2.0);
  // The projected box holds every pixel of its silhouette.
  EXPECT_LE(t.box.u0, t.pixels.u0 + 1.0);
  EXPECT_GE(t.box.u1, t.pixels.u1 - 1.0);
  EXPECT_LE(t.box.v0, t.pixels.v0 + 1.0);
  EXPECT_GE(t.box.v1, t.pixels.v1 - 1.0);
  // White shell, dark joints and the jersey: several distinct shades, not one flat colour.
  int white = 0, dark = 0;
  const auto bgr = r.bgr();
  for (std::size_t i = 0; i < r.labels().size(); ++i) {
    if (r.labels()[i] != PixelLabel::kRobot) continue;
    const hal::Yuv c = hal::bgr_to_yuv(bgr[3 * i], bgr[3 * i + 1], bgr[3 * i + 2]);
    if (c.y > 150) ++white;
    if (c.y < 80) ++dark;
  }
  EXPECT_GT(white, 200);
  EXPECT_GT(dark, 50);
  // Nothing of the old cylinder: beside the shins, within its 0.15 m, the carpet shows through.
  const auto gap = pixel_of(r.spec(), hal::HeadJoints{0.0, 0.1}, {2.0, 0.3 + 0.14, 0.1});
  EXPECT_NE(label_at(r, gap), PixelLabel::kRobot) << "the old cylinder was 0.3 m wide all the way up";
}

TEST(SimCameraLook, SameSeedSameBytesNoiseChangesEveryFrame) {
  World world = spl_world();
  world.look.style = LookStyle::kSpl;
  CameraRenderer a(world, small_camera(), 9);
  CameraRenderer b(world, small_camera(), 9);
  a.render(kViews[0], hal::HeadJoints{0.0, 0.4});
  b.render(kViews[0], hal::HeadJoints{0.0, 0.4});
  const std::vector<std::uint8_t> first(a.bgr().begin(), a.bgr().end());
  EXPECT_TRUE(std::equal(first.begin(), first.end(), b.bgr().begin()));
  a.render(kViews[0], hal::HeadJoints{0.0, 0.4});
  EXPECT_FALSE(std::equal(first.begin(), first.end(), a.bgr().begin())) << "sensor noise is new every frame";
}

double mean_carpet_y(const CameraRenderer& r) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < r.labels().size(); ++i) {
    if (r.labels()[i] != PixelLabel::kCarpet) continue;
    sum += hal::bgr_to_yuv(r.bgr()[3 * i], r.bgr()[3 * i + 1], r.bgr()[3 * i + 2]).y;
    ++n;
  }
  return sum / n;
}

TEST(SimCameraLook, AutoExposureDriftsSlowly) {
  World world = spl_world();
  world.look.style = LookStyle::kSpl;
  world.look.drift = 0.15;
  world.look.drift_frames = 20.0;
  CameraRenderer r(std::move(world), small_camera(), 4);
  std::vector<double> y;
  for (int f = 0; f < 120; ++f) {
    r.render(kViews[0], hal::HeadJoints{0.0, 0.42});
    y.push_back(mean_carpet_y(r));
  }
  const auto [lo, hi] = std::minmax_element(y.begin(), y.end());
  EXPECT_GT(*hi - *lo, 6.0) << "the exposure wanders";
  for (std::size_t f = 1; f < y.size(); ++f) EXPECT_LT(std::abs(y[f] - y[f - 1]), 3.0) << "but slowly, frame " << f;
}

double horizontal_gradient(const CameraRenderer& r) {
  const int w = r.spec().intrinsics.width;
  double sum = 0.0;
  for (std::size_t i = 1; i < r.labels().size(); ++i) {
    if (static_cast<int>(i % static_cast<std::size_t>(w)) == 0) continue;
    sum += std::abs(int(r.bgr()[3 * i + 1]) - int(r.bgr()[3 * i - 2]));
  }
  return sum;
}

TEST(SimCameraLook, MotionBlurSmearsAlongItsDirection) {
  World world = spl_world();
  world.look.style = LookStyle::kSpl;
  world.look.noise = 0.0;
  CameraRenderer sharp(world, small_camera(), 2);
  world.look.blur = 7;
  CameraRenderer blurred(world, small_camera(), 2);
  sharp.render(kViews[0], hal::HeadJoints{0.0, 0.42});
  blurred.render(kViews[0], hal::HeadJoints{0.0, 0.42});
  EXPECT_LT(horizontal_gradient(blurred), 0.5 * horizontal_gradient(sharp));
  // Labels stay the scene's: blur is the camera's, not the world's.
  EXPECT_TRUE(std::equal(sharp.labels().begin(), sharp.labels().end(), blurred.labels().begin()));
}

TEST(SimCameraLook, TheWorldFileChoosesTheLook) {
  const std::string head = "ringlet-world 2\nbounds 0 0 10 10\nstart 1 1 0\n";
  EXPECT_EQ(parse_world(head, "t").look.style, LookStyle::kPlain);
  const World spl = parse_world(head + "look spl\n", "t");
  EXPECT_EQ(spl.look.style, LookStyle::kSpl);
  EXPECT_EQ(spl.look.ball, BallLook::kBlackWhite);
  const World orange = parse_world(head + "look spl orange backlight\n", "t");
  EXPECT_EQ(orange.look.ball, BallLook::kOrange);
  EXPECT_EQ(orange.look.light, LightKind::kBacklight);
  EXPECT_LT(orange.look.exposure, 1.0);
  const auto error = [&](const std::string& text) {
    try {
      (void)parse_world(text, "t.world");
    } catch (const WorldError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error(head + "look shiny\n"), "t.world:4: look: style must be plain or spl, got 'shiny'");
  EXPECT_EQ(error(head + "look spl red\n"), "t.world:4: look: ball must be orange or bw, got 'red'");
  EXPECT_EQ(error(head + "look spl bw candle\n"),
            "t.world:4: look: light must be fluorescent, daylight or backlight, got 'candle'");
  EXPECT_EQ(error(head + "look spl\nlook plain\n"), "t.world:5: look: given twice (first on line 4)");
  EXPECT_EQ(error("ringlet-world 1\nbounds 0 0 10 10\nstart 1 1 0\nlook spl\n"),
            "t.world:4: look: this statement needs format version 2 (the header on line 1 says 1)");
}

}  // namespace
}  // namespace ringlet::sim_hal
