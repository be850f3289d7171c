// The torso's tilt in vision: the horizon comes from the whole chain (ground → tilted torso → head
// → camera), so leaning forward moves it like more head pitch and rolling slants it; and the
// pipeline, told the posture, puts a tilted camera's lines and ball where they are on the ground.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ringlet/vision/horizon.hpp"
#include "ringlet/vision/pipeline.hpp"
#include "synthetic_field.hpp"

namespace ringlet::vision {
namespace {

using testing::Camera;

// 5° of forward lean with the head straight ahead is 5° more head pitch: the same horizon in
// every column (the pivot moves a little, the horizon is a direction and does not).
TEST(HorizonBody, ForwardLeanMovesTheHorizonLikeHeadPitch) {
  const auto k = hal::CameraIntrinsics::nao();
  const hal::CameraMount mount{};
  for (const double lean_deg : {5.0, -3.0, 12.0}) {
    const double lean = hal::deg_to_rad(lean_deg);
    const auto tilted = hal::CameraPose::from_body(mount, {lean, 0.0}, {0.0, 0.25});
    const auto more_head = hal::CameraPose::from_head(mount, {0.0, 0.25 + lean});
    const auto upright = hal::CameraPose::from_head(mount, {0.0, 0.25});
    for (const double u : {0.0, 320.0, 639.0}) {
      EXPECT_NEAR(horizon_v(k, tilted, u), horizon_v(k, more_head, u), 1e-9) << lean_deg;
      // By the right amount: v = cy − fy·tan(pitch).
      EXPECT_NEAR(horizon_v(k, tilted, u), k.cy - k.fy * std::tan(0.25 + lean), 1e-9);
    }
    // Leaning forward raises the horizon in the picture (the camera looks further down).
    if (lean > 0.0) {
      EXPECT_LT(horizon_v(k, tilted, 320.0), horizon_v(k, upright, 320.0));
    }
    std::vector<int> a(640), b(640);
    EXPECT_EQ(horizon_rows(k, tilted, 2, a), horizon_rows(k, more_head, 2, b));
    EXPECT_EQ(a, b);
  }
}

// Roll slants the horizon by the roll angle (exactly, with the head level and fx = fy; within a
// degree at the usual head pitch): positive roll, leaning right, raises its right end.
TEST(HorizonBody, RollSlantsTheHorizonByTheRollAngle) {
  hal::CameraIntrinsics k = hal::CameraIntrinsics::nao();
  k.fy = k.fx;  // square pixels: the picture's slant is then the roll itself
  const hal::CameraMount mount{};
  for (const double roll_deg : {4.0, -7.0, 15.0}) {
    const double roll = hal::deg_to_rad(roll_deg);
    const auto level = hal::CameraPose::from_body(mount, {0.0, roll}, {0.0, 0.0});
    const double slope = (horizon_v(k, level, 639.0) - horizon_v(k, level, 0.0)) / 639.0;
    EXPECT_NEAR(std::atan(-slope), roll, 1e-12) << roll_deg;
    const auto pitched = hal::CameraPose::from_body(mount, {0.0, roll}, {0.0, 0.35});
    const double pitched_slope = (horizon_v(k, pitched, 639.0) - horizon_v(k, pitched, 0.0)) / 639.0;
    EXPECT_NEAR(std::atan(-pitched_slope), roll, hal::deg_to_rad(1.0)) << roll_deg;
    // Leaning right: the right end is higher in the picture (smaller v).
    if (roll > 0.0) {
      EXPECT_LT(horizon_v(k, pitched, 639.0), horizon_v(k, pitched, 0.0));
    }
  }
}

// With a slanted horizon each column's first ground row is its own: its pixel centre's ray meets
// the ground, the row above's does not.
TEST(HorizonBody, FirstGroundRowIsRightInEveryColumnOfARolledCamera) {
  const auto k = hal::CameraIntrinsics::nao();
  const auto pose = hal::CameraPose::from_body(hal::CameraMount{}, {hal::deg_to_rad(4.0), hal::deg_to_rad(-9.0)},
                                               {0.3, 0.05});
  std::vector<int> rows(640);
  const int lowest = horizon_rows(k, pose, 0, rows);
  EXPECT_EQ(lowest, *std::min_element(rows.begin(), rows.end()));
  int inside = 0;
  for (int u = 0; u < 640; ++u) {
    const int row = rows[static_cast<std::size_t>(u)];
    const double uc = u + 0.5;
    if (row > 0 && row < 480) {
      ++inside;
      EXPECT_TRUE(hal::pixel_to_ground(k, pose, {uc, row + 0.5}).has_value()) << u;
      EXPECT_FALSE(hal::pixel_to_ground(k, pose, {uc, row - 0.5}).has_value()) << u;
    }
  }
  EXPECT_EQ(inside, 640);  // the horizon crosses the whole picture here
  // And it is slanted: leaning left (negative roll) lowers its right end, by about tan(9°)·640 rows.
  EXPECT_GT(rows.back() - rows.front(), 80);
}

// The synthetic field seen by a leaning robot: told the posture, the pipeline finds the lines and
// the ball where they are; told "upright", the ball's ground position is far off.
TEST(PipelineBody, ATiltedCameraToldItsPostureFindsTheFieldWhereItIs) {
  Camera cam;
  cam.body = {hal::deg_to_rad(6.0), hal::deg_to_rad(4.0)};
  cam.head = {0.0, 0.35 - hal::deg_to_rad(6.0)};
  const auto frame = testing::render(testing::field_scene(), cam, hal::PixelFormat::kYuyv, 17);
  VisionPipeline p(VisionConfig{}, ColourTable::from_thresholds(ColourThresholds{}));
  const VisionResult r = p.process(frame.view, cam.posture());
  ASSERT_EQ(r.status, VisionStatus::kOk);
  EXPECT_EQ(r.posture.body.roll, cam.body.roll);
  ASSERT_TRUE(r.ball.seen);
  ASSERT_TRUE(r.ball.ground_valid);
  EXPECT_NEAR(r.ball.ground.x, 1.4, 0.05);
  EXPECT_NEAR(r.ball.ground.y, -0.4, 0.05);
  int halfway = 0;
  for (std::size_t i = 0; i < r.line_count; ++i) {
    const FieldLine& f = r.lines[i];
    if (std::abs(f.ground_start.x - 3.0) < 0.1 && std::abs(f.ground_end.x - 3.0) < 0.1) ++halfway;
  }
  EXPECT_GE(halfway, 1);

  const VisionResult upright = p.process(frame.view, cam.head);
  EXPECT_NE(upright.horizon_row, r.horizon_row);
  if (upright.ball.seen && upright.ball.ground_valid) {
    EXPECT_GT(std::hypot(upright.ball.ground.x - 1.4, upright.ball.ground.y + 0.4), 0.2);
  }
}

}  // namespace
}  // namespace ringlet::vision
