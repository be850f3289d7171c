// LineCheck: a fitted piece is kept only where the classified picture shows paint with field on
// both sides (vision/include/ringlet/vision/line_check.hpp).
#include <gtest/gtest.h>

#include <vector>

#include "ringlet/vision/class_image.hpp"
#include "ringlet/vision/colour_table.hpp"
#include "ringlet/vision/horizon.hpp"
#include "ringlet/vision/line_check.hpp"
#include "synthetic_field.hpp"

namespace ringlet::vision {
namespace {

using testing::Camera;

// Classifies `scene` as the camera sees it and asks the checker about the ground segment [a, b].
double share(const testing::Scene& scene, hal::RobotPoint a, hal::RobotPoint b, int step = 1,
             const LineCheckParams& params = {}) {
  const Camera cam;
  const auto f = testing::render(scene, cam, hal::PixelFormat::kYuyv);
  std::vector<int> rows(640);
  const int first = horizon_rows(cam.k, cam.pose(), 2, rows);
  ClassImage classes(640, 480);
  EXPECT_TRUE(classes.classify(f.view, ColourTable::from_thresholds({}), first, step));
  const hal::CameraPose pose = cam.pose();
  return LineCheck(classes, cam.k, pose, params).share(a, b);
}

// The same picture, asked for the painted part of [a, b].
LineCheck::Span painted(const testing::Scene& scene, hal::RobotPoint a, hal::RobotPoint b) {
  const Camera cam;
  const auto f = testing::render(scene, cam, hal::PixelFormat::kYuyv);
  std::vector<int> rows(640);
  const int first = horizon_rows(cam.k, cam.pose(), 2, rows);
  ClassImage classes(640, 480);
  EXPECT_TRUE(classes.classify(f.view, ColourTable::from_thresholds({}), first, 1));
  const hal::CameraPose pose = cam.pose();
  return LineCheck(classes, cam.k, pose, {}).painted_span(a, b);
}

testing::Scene one_line() {
  testing::Scene scene;
  scene.lines = {{{1.5, -2.0}, {1.5, 2.0}}};  // across the view, 1.5 m ahead
  return scene;
}

TEST(LineCheck, APaintedLinePassesAllAlongIt) {
  EXPECT_DOUBLE_EQ(share(one_line(), {1.5, -0.8}, {1.5, 0.8}), 1.0);
  EXPECT_DOUBLE_EQ(share(one_line(), {1.5, -0.8}, {1.5, 0.8}, 2), 1.0) << "on the coarser class grid too";
  // A fit a centimetre off the paint is still on it.
  EXPECT_DOUBLE_EQ(share(one_line(), {1.51, -0.8}, {1.51, 0.8}), 1.0);
}

TEST(LineCheck, AFitAcrossPlainGreenFails) {
  EXPECT_LE(share(one_line(), {1.0, -0.5}, {2.2, 0.5}), 0.2) << "crosses the line once, green elsewhere";
  EXPECT_DOUBLE_EQ(share(one_line(), {1.2, -0.8}, {1.2, 0.8}), 0.0) << "parallel to the paint, 30 cm before it";
}

TEST(LineCheck, AWhiteBlobIsNoLine) {
  // A robot's feet: a white box half a metre wide, its long side along the "line".
  testing::Scene scene;
  scene.blobs = {{{1.4, -0.3}, {1.9, 0.3}}};
  EXPECT_LT(share(scene, {1.65, -0.25}, {1.65, 0.25}), 0.5) << "paint, but far too wide";
}

TEST(LineCheck, ALineHalfHiddenByTheBallStillPasses) {
  testing::Scene scene = one_line();
  scene.ball = hal::RobotPoint{1.5, 0.0};
  scene.ball_radius = 0.1;
  const double s = share(scene, {1.5, -0.4}, {1.5, 0.4});
  EXPECT_GE(s, 0.5);
  EXPECT_LT(s, 1.0) << "the samples behind the ball do not look like paint";
}

TEST(LineCheck, APieceRunningPastThePaintIsCutBackToIt) {
  // The paint runs along y from -0.4 to 0.4 at x = 1.5; the piece runs on to y = 0.8 (a fit
  // carried on by stray points in line with it).
  testing::Scene scene;
  scene.lines = {{{1.5, -0.4}, {1.5, 0.4}}};
  const LineCheck::Span s = painted(scene, {1.5, -0.4}, {1.5, 0.8});
  EXPECT_DOUBLE_EQ(s.from, 0.0);
  // Paint ends two thirds of the way along (0.8 of 1.2 m); the cut lies within one of the 24
  // samples (0.05 m) of it.
  EXPECT_NEAR(s.to, 0.8 / 1.2, 1.0 / 24.0 + 1e-9);
  // All along the paint: nothing to cut.
  const LineCheck::Span all = painted(one_line(), {1.5, -0.8}, {1.5, 0.8});
  EXPECT_DOUBLE_EQ(all.from, 0.0);
  EXPECT_DOUBLE_EQ(all.to, 1.0);
}

// A line across the view at distance x, painted in dashes `on` long with gaps `off` between them
// (a far line as a renderer aliases it, or as a camera's faint paint flickers between classes).
testing::Scene dashed_line(double x, double on, double off) {
  testing::Scene scene;
  for (double y = -1.5; y < 1.5; y += on + off) scene.lines.push_back({{x, y}, {x, y + on}});
  return scene;
}

// Half the painted width in the picture at `at` of a line across the view (along y).
double half_width_at(hal::RobotPoint at) {
  const Camera cam;
  const ClassImage classes(640, 480);
  const hal::CameraPose pose = cam.pose();
  return LineCheck(classes, cam.k, pose, {}).half_width_px(at, 0.0, 1.0);
}

TEST(LineCheck, AThinFarLineInDashesPassesOverAShortStretch) {
  // 4 m ahead the paint is about two pixels wide; 5 cm dashes with 5 cm gaps.
  const hal::RobotPoint a{4.0, -0.6}, b{4.0, 0.6};
  ASSERT_LT(half_width_at(a), LineCheckParams{}.thin_half_width_px) << "the scene must show a thin band";
  const testing::Scene scene = dashed_line(4.0, 0.05, 0.05);
  LineCheckParams point_only;
  point_only.thin_reach_px = 0;  // judged at the sample's pixel alone
  const double alone = share(scene, a, b, 1, point_only);
  const double stretch = share(scene, a, b);
  EXPECT_LT(alone, 0.75) << "samples in the gaps fail on their own pixel";
  EXPECT_GE(stretch, 0.95) << "a dash within the stretch carries the sample";
  // Plain green at that distance still fails: the stretch looks along the line, not across it.
  EXPECT_DOUBLE_EQ(share(scene, {4.4, -0.6}, {4.4, 0.6}), 0.0);
}

TEST(LineCheck, AWideNearLineIsJudgedAtItsSamplesOnly) {
  // 1.5 m ahead the paint is wide: its gaps are real gaps (an occluder, the line's end).
  const hal::RobotPoint a{1.5, -0.6}, b{1.5, 0.6};
  ASSERT_GE(half_width_at(a), LineCheckParams{}.thin_half_width_px);
  const testing::Scene scene = dashed_line(1.5, 0.05, 0.05);
  LineCheckParams point_only;
  point_only.thin_reach_px = 0;
  EXPECT_DOUBLE_EQ(share(scene, a, b), share(scene, a, b, 1, point_only));
}

TEST(LineCheck, OffOrOutOfThePictureIsNotJudged) {
  LineCheckParams off;
  off.enabled = false;
  const Camera cam;
  const ClassImage classes(640, 480);
  const hal::CameraPose pose = cam.pose();
  EXPECT_TRUE(LineCheck(classes, cam.k, pose, off).accepts({1.0, -0.5}, {2.2, 0.5})) << "disabled: accepts all";
  // Behind the camera: no sample inside the picture, so too few to judge: kept.
  EXPECT_DOUBLE_EQ(share(one_line(), {-2.0, -0.5}, {-2.0, 0.5}), 1.0);
}


// A near line along the bottom of the picture: the picture's edge cuts its band, which has field
// on its far side only. The edge says nothing against paint: before, such a band was "no field
// beyond it" and failed.
TEST(LineCheck, ABandTheEdgeOfThePictureCutsIsPaint) {
  const Camera cam;
  const auto bottom = hal::pixel_to_ground(cam.k, cam.pose(), {320.0, 480.0});
  ASSERT_TRUE(bottom.has_value());
  // The centre line 1.5 cm beyond the bottom row's ground: a band 5 cm wide is cut a centimetre
  // short of its near edge.
  const double x = bottom->x + 0.015;
  testing::Scene scene;
  scene.lines = {{{x, -2.0}, {x, 2.0}}};
  EXPECT_GE(share(scene, {x, -0.3}, {x, 0.3}), 0.9);
  // Clear of the edge, the same line passes as before; green beyond a band is still needed.
  scene.lines = {{{x + 0.3, -2.0}, {x + 0.3, 2.0}}};
  EXPECT_DOUBLE_EQ(share(scene, {x + 0.3, -0.3}, {x + 0.3, 0.3}), 1.0);
}

}  // namespace
}  // namespace ringlet::vision
