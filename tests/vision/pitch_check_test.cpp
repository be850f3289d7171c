// The head pitch from the field lines (pitch_check.hpp): lines that are square on the ground,
// seen through a camera whose pitch is given wrong, give back the offset; one pair, pieces of one
// line, or lines no pitch squares give no estimate; and on a rendered frame the whole correction
// (run, estimate, run again) finds the camera's pitch.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ringlet/hal/geometry.hpp"
#include "ringlet/vision/pitch_check.hpp"
#include "synthetic_field.hpp"

namespace ringlet::vision {
namespace {

using testing::Camera;

// A penalty area's corner region ahead and to the left, as the true camera sees it.
std::vector<ImageSegment> seen(const Camera& cam, const std::vector<std::pair<hal::RobotPoint, hal::RobotPoint>>& ground) {
  std::vector<ImageSegment> out;
  for (const auto& [a, b] : ground) {
    const auto pa = hal::project(cam.k, cam.pose(), {a.x, a.y, 0.0});
    const auto pb = hal::project(cam.k, cam.pose(), {b.x, b.y, 0.0});
    if (pa && pb) out.push_back({*pa, *pb});
  }
  return out;
}

const std::vector<std::pair<hal::RobotPoint, hal::RobotPoint>> kBox{
    {{1.2, -0.6}, {1.2, 0.9}},  // across the view
    {{1.2, 0.9}, {2.6, 0.9}},   // away, to the left
    {{2.6, -0.6}, {2.6, 0.9}},  // the far side, parallel to the first
    {{1.2, -0.6}, {2.2, -0.6}}, // away, to the right
};

Camera test_camera() {
  Camera cam;
  cam.head = {0.15, 0.30};
  return cam;
}

TEST(PitchCheck, SquareLinesGiveBackHowFarThePitchIsOff) {
  const Camera cam = test_camera();
  const std::vector<ImageSegment> segments = seen(cam, kBox);
  ASSERT_EQ(segments.size(), 4U);
  for (const double error_deg : {3.0, -2.0, 5.5, -6.0}) {
    hal::CameraPosture told = cam.posture();
    told.head.pitch += hal::deg_to_rad(error_deg);
    const PitchCheck c = estimate_pitch_offset(segments, cam.k, cam.mount, told);
    ASSERT_TRUE(c.valid) << error_deg;
    EXPECT_NEAR(c.offset_deg, -error_deg, 0.051) << error_deg;
    EXPECT_EQ(c.segments, 4);
    EXPECT_EQ(c.pairs, 6);
    EXPECT_LT(c.residual_deg, 0.2) << error_deg;
    EXPECT_GT(c.residual_at_given_deg, 1.0) << error_deg;  // the wrong pitch bends them visibly
  }
}

TEST(PitchCheck, AtTheRightPitchNothingMoves) {
  const Camera cam = test_camera();
  const PitchCheck c = estimate_pitch_offset(seen(cam, kBox), cam.k, cam.mount, cam.posture());
  ASSERT_TRUE(c.valid);
  EXPECT_NEAR(c.offset_deg, 0.0, 0.051);
  EXPECT_LT(c.residual_at_given_deg, 0.2);
}

TEST(PitchCheck, OnePairIsNoEvidence) {
  // Any one pair can be squared by some pitch: two lines never make an estimate.
  const Camera cam = test_camera();
  const std::vector<ImageSegment> two = seen(cam, {kBox[0], kBox[1]});
  hal::CameraPosture told = cam.posture();
  told.head.pitch += hal::deg_to_rad(3.0);
  const PitchCheck c = estimate_pitch_offset(two, cam.k, cam.mount, told);
  EXPECT_FALSE(c.valid);
  EXPECT_EQ(c.pairs, 1);
}

TEST(PitchCheck, PiecesOfOneLineAreNoPair) {
  const Camera cam = test_camera();
  const std::vector<ImageSegment> pieces =
      seen(cam, {{{1.2, -0.6}, {1.2, -0.1}}, {{1.2, 0.0}, {1.2, 0.4}}, {{1.2, 0.5}, {1.2, 0.9}}});
  const PitchCheck c = estimate_pitch_offset(pieces, cam.k, cam.mount, cam.posture());
  EXPECT_FALSE(c.valid);
  EXPECT_EQ(c.segments, 3);
  EXPECT_EQ(c.pairs, 0);
}

TEST(PitchCheck, LinesNoPitchSquaresGiveNoEstimate) {
  // At 35° and 65° to each other: not field lines (arc pieces, a post's edges); no pitch in range
  // squares them, so nothing is corrected.
  const Camera cam = test_camera();
  const std::vector<ImageSegment> skew = seen(cam, {{{1.0, -0.5}, {2.0, 0.2}}, {{1.5, 0.6}, {2.5, 0.4}}, {{1.1, 0.8}, {1.3, -0.4}}});
  const PitchCheck c = estimate_pitch_offset(skew, cam.k, cam.mount, cam.posture());
  EXPECT_FALSE(c.valid);
  EXPECT_EQ(c.pairs, 3);
  EXPECT_GT(c.residual_deg, PitchCheckParams{}.max_residual_deg);
}

TEST(PitchCheck, ShortSegmentsAndSegmentsOffTheGroundAreNotUsed) {
  const Camera cam = test_camera();
  std::vector<ImageSegment> segments = seen(cam, kBox);
  segments.push_back({{100.0, 300.0}, {120.0, 300.0}});  // 20 px: too short to give a direction
  segments.push_back({{10.0, 5.0}, {300.0, 5.0}});       // above the horizon
  const PitchCheck c = estimate_pitch_offset(segments, cam.k, cam.mount, cam.posture());
  EXPECT_EQ(c.segments, 4);
}

TEST(PitchCheck, CorrectHeadPitchFindsTheCameraFromARenderedFrame) {
  Camera cam = test_camera();
  testing::Scene scene;
  for (const auto& [a, b] : kBox) scene.lines.push_back({a, b});
  const testing::Frame frame = testing::render(scene, cam, hal::PixelFormat::kYuyv);
  VisionConfig config;
  config.intrinsics = cam.k;
  config.mount = cam.mount;
  VisionPipeline pipeline(config, ColourTable::from_thresholds(ColourThresholds{}));
  for (const double error_deg : {3.0, -3.0}) {
    hal::CameraPosture told = cam.posture();
    told.head.pitch += hal::deg_to_rad(error_deg);
    const PitchCorrection c = correct_head_pitch(pipeline, frame.view, told);
    ASSERT_TRUE(c.corrected()) << error_deg;
    EXPECT_NEAR(hal::rad_to_deg(c.posture.head.pitch), hal::rad_to_deg(cam.head.pitch), 0.3) << error_deg;
    EXPECT_EQ(c.posture.head.yaw, cam.head.yaw);
  }
  // Told the right pitch, it stays within what the detected ends allow (0.25° here).
  const PitchCorrection same = correct_head_pitch(pipeline, frame.view, cam.posture());
  EXPECT_NEAR(hal::rad_to_deg(same.posture.head.pitch), hal::rad_to_deg(cam.head.pitch), 0.3);
}

}  // namespace
}  // namespace ringlet::vision
