// The penalty and centre marks (vision/include/ringlet/vision/field_marks.hpp): a painted cross
// on rendered carpet is found where it lies, with its orientation; a square blob, a short line
// stub, a ball and a cross on a line are not crosses; the work is bounded.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "ringlet/vision/field_marks.hpp"
#include "ringlet/vision/pipeline.hpp"
#include "synthetic_field.hpp"

namespace ringlet::vision {
namespace {

using testing::Camera;

constexpr double kDeg = std::numbers::pi / 180.0;

// A 10 cm cross of 5 cm bars at `c`, one bar turned `angle` from the robot's x axis.
void add_cross(testing::Scene& scene, hal::RobotPoint c, double angle) {
  const double h = 0.05;
  const double ux = std::cos(angle) * h, uy = std::sin(angle) * h;
  scene.lines.push_back({{c.x - ux, c.y - uy}, {c.x + ux, c.y + uy}});
  scene.lines.push_back({{c.x + uy, c.y - ux}, {c.x - uy, c.y + ux}});
}

const FieldMarkList& run(VisionPipeline& p, const testing::Scene& scene) {
  const Camera cam;
  const auto frame = testing::render(scene, cam, hal::PixelFormat::kYuyv);
  return p.process(frame.view, cam.head).marks;
}

VisionPipeline make() { return VisionPipeline(VisionConfig{}, ColourTable::from_thresholds({})); }

// The difference of two cross orientations, which repeat every 90°.
double cross_angle_error(double a, double b) {
  const double d = std::fmod(std::abs(a - b), std::numbers::pi / 2.0);
  return std::min(d, std::numbers::pi / 2.0 - d);
}

TEST(FieldMarks, ACrossIsFoundWhereItLiesWithItsOrientation) {
  VisionPipeline p = make();
  for (const double angle : {0.0, 20.0 * kDeg, 37.0 * kDeg, 70.0 * kDeg}) {
    for (const hal::RobotPoint c : {hal::RobotPoint{1.2, 0.2}, hal::RobotPoint{2.0, -0.4}}) {
      testing::Scene scene;
      scene.lines = {{{4.0, -3.0}, {4.0, 3.0}}};  // a line well beyond it
      add_cross(scene, c, angle);
      const FieldMarkList& m = run(p, scene);
      ASSERT_EQ(m.count, 1U) << "cross at (" << c.x << ", " << c.y << ") turned " << angle / kDeg << "°";
      EXPECT_NEAR(m.marks[0].centre.x, c.x, 0.02);
      EXPECT_NEAR(m.marks[0].centre.y, c.y, 0.02);
      EXPECT_LT(cross_angle_error(m.marks[0].orientation_rad, angle), 3.0 * kDeg)
          << "found " << m.marks[0].orientation_rad / kDeg << "° for " << angle / kDeg << "°";
      EXPECT_GE(m.marks[0].orientation_rad, 0.0);
      EXPECT_LT(m.marks[0].orientation_rad, std::numbers::pi / 2.0);
      EXPECT_GE(m.marks[0].confidence, 0.9);
      EXPECT_NEAR(m.marks[0].distance_m, std::hypot(c.x, c.y), 0.02);
      EXPECT_NEAR(m.marks[0].bearing_rad, std::atan2(c.y, c.x), 0.02);
    }
  }
}

TEST(FieldMarks, BlobsStubsBallsAndCrossesOnLinesAreNoMarks) {
  VisionPipeline p = make();
  testing::Scene blob;  // a white square as large as a cross: paint in its corners too
  blob.blobs = {{{1.45, -0.05}, {1.55, 0.05}}};
  EXPECT_EQ(run(p, blob).count, 0U) << "a square";
  testing::Scene stub;  // a 12 cm piece of line: one bar, no cross
  stub.lines = {{{1.5, -0.06}, {1.5, 0.06}}};
  EXPECT_EQ(run(p, stub).count, 0U) << "a stub";
  testing::Scene ball;
  ball.ball = hal::RobotPoint{1.5, 0.1};
  ball.ball_black_white = true;
  EXPECT_EQ(run(p, ball).count, 0U) << "the ball";
  testing::Scene crossing;  // a cross on a long line (the centre mark on the halfway line): the line's
  crossing.lines = {{{1.5, -2.0}, {1.5, 2.0}}};
  add_cross(crossing, {1.5, 0.0}, 0.0);
  EXPECT_EQ(run(p, crossing).count, 0U) << "a cross on a line";
}

TEST(FieldMarks, TheWorkIsBoundedByMaxPoints) {
  // Scattered leftovers (no lines, nothing classified): at most max_points are examined.
  FieldMarkParams params;
  params.max_points = 16;
  FieldMarkFinder finder(params, 1000);
  std::vector<CandidatePoint> points;
  for (int i = 0; i < 200; ++i) points.push_back({{}, {0.5 + 0.02 * i, 0.0}, 3.0F, ScanDirection::kVertical});
  const Camera cam;
  const hal::CameraPose pose = cam.pose();
  ClassImage classes(640, 480);
  FieldMarkList out;
  finder.find(points, {}, CentreCircle{}, {}, classes, cam.k, pose, Deadline{}, out);
  EXPECT_EQ(out.leftovers, 16);
  EXPECT_LE(out.tests, 3 * 16 * 16 + 16 * (12 + 144 + 13 + 1));
  EXPECT_EQ(out.count, 0U) << "nothing classified: no cross in the picture";
}

TEST(FieldMarks, TheBarsAreTheCrossTurned) {
  FieldMark m;
  m.centre = {2.0, 1.0};
  m.orientation_rad = 30.0 * kDeg;
  const auto bars = FieldMarkFinder::bars(m);
  for (const auto& bar : bars) {
    EXPECT_NEAR(std::hypot(bar[1].x - bar[0].x, bar[1].y - bar[0].y), 0.10, 1e-12);
    EXPECT_NEAR((bar[0].x + bar[1].x) / 2.0, 2.0, 1e-12);
    EXPECT_NEAR((bar[0].y + bar[1].y) / 2.0, 1.0, 1e-12);
  }
  EXPECT_NEAR(std::atan2(bars[0][1].y - bars[0][0].y, bars[0][1].x - bars[0][0].x), 30.0 * kDeg, 1e-12);
  const double dot = (bars[0][1].x - bars[0][0].x) * (bars[1][1].x - bars[1][0].x) +
                     (bars[0][1].y - bars[0][0].y) * (bars[1][1].y - bars[1][0].y);
  EXPECT_NEAR(dot, 0.0, 1e-12) << "at right angles";
}

}  // namespace
}  // namespace ringlet::vision
