// The ball on synthetic frames: found where it lies, at the radius it should have, with high
// confidence; nothing found on an empty field; a long orange strip is not round.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ringlet/vision/ball.hpp"
#include "ringlet/vision/horizon.hpp"
#include "synthetic_field.hpp"

namespace ringlet::vision {
namespace {

using testing::Camera;

BallDetection detect(const testing::Scene& scene, const Camera& cam, int step = 1) {
  const auto f = testing::render(scene, cam, hal::PixelFormat::kYuyv);
  std::vector<int> rows(640);
  const int first = horizon_rows(cam.k, cam.pose(), 2, rows);
  ClassImage classes(640, 480);
  EXPECT_TRUE(classes.classify(f.view, ColourTable::from_thresholds({}), first, step));
  BallDetector d({}, 640, 480);
  return d.detect(classes, cam.k, cam.pose());
}

TEST(Ball, FoundWhereItLies) {
  Camera cam;
  for (const hal::RobotPoint at : {hal::RobotPoint{1.4, -0.4}, hal::RobotPoint{0.9, 0.2}, hal::RobotPoint{3.0, 0.5}}) {
    testing::Scene scene = testing::field_scene();
    scene.ball = at;
    for (const int step : {1, 2}) {
      const BallDetection b = detect(scene, cam, step);
      ASSERT_TRUE(b.seen) << at.x;
      ASSERT_TRUE(b.ground_valid);
      EXPECT_NEAR(b.ground.x, at.x, 0.03 * at.x) << at.x << " step " << step;
      EXPECT_NEAR(b.ground.y, at.y, 0.03) << at.x << " step " << step;
      // Its image: centred on the projection of the ball's centre, radius ≈ fx·R/depth.
      const auto c = hal::project(cam.k, cam.pose(), {at.x, at.y, 0.05});
      ASSERT_TRUE(c);
      EXPECT_NEAR(b.centre.u, c->u, 1.5);
      EXPECT_NEAR(b.centre.v, c->v, 1.5);
      const hal::Vec3 cc = cam.pose().to_camera({at.x, at.y, 0.05});
      const double depth = std::sqrt(cc.x * cc.x + cc.y * cc.y + cc.z * cc.z);
      EXPECT_NEAR(b.radius_px, cam.k.fx * 0.05 / depth, 1.0 + step);
      EXPECT_GT(b.confidence, 0.7) << at.x;
    }
  }
}

TEST(Ball, NoneOnAnEmptyField) {
  Camera cam;
  testing::Scene scene = testing::field_scene();
  scene.ball.reset();
  EXPECT_FALSE(detect(scene, cam).seen);
}

}  // namespace
}  // namespace ringlet::vision
