// Scan-line candidates on synthetic frames: run centres land on the painted line's centre (within
// 1 px of its projection), white blobs too wide for a line are refused, lines running down the
// image are found by the horizontal scans.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ringlet/vision/horizon.hpp"
#include "ringlet/vision/scan_points.hpp"
#include "synthetic_field.hpp"

namespace ringlet::vision {
namespace {

using testing::Camera;

struct Scanned {
  std::vector<CandidatePoint> points;
  ScanStats stats;
};

Scanned scan(const testing::Scene& scene, const Camera& cam, ScanParams params = {}, int step = 1) {
  const auto f = testing::render(scene, cam, hal::PixelFormat::kYuyv);
  const ColourTable table = ColourTable::from_thresholds({});
  std::vector<int> rows(640);
  const int first = horizon_rows(cam.k, cam.pose(), 2, rows);
  ClassImage classes(640, 480);
  EXPECT_TRUE(classes.classify(f.view, table, first, step));
  CandidateBuffer out(4096);
  Scanned s;
  LineScanner scanner(640);
  s.stats = scanner.scan(classes, f.view, cam.k, cam.pose(), rows, params, out);
  s.points.assign(out.points().begin(), out.points().end());
  EXPECT_EQ(out.dropped(), 0U);
  return s;
}

TEST(ScanPoints, LineAcrossTheViewGivesItsCentreInEveryColumn) {
  Camera cam;
  testing::Scene scene;
  scene.lines = {{{1.5, -3.0}, {1.5, 3.0}}};
  ScanParams params;
  params.horizontal = false;
  const Scanned s = scan(scene, cam, params);
  ASSERT_EQ(s.points.size(), 320U);  // every other column, one crossing each
  const auto pose = cam.pose();
  for (const CandidatePoint& p : s.points) {
    EXPECT_EQ(p.direction, ScanDirection::kVertical);
    EXPECT_NEAR(p.ground.x, 1.5, 0.02);
    // Exact expectation: the projection of the line's centre at this ground y.
    const auto expected = hal::project(cam.k, pose, {1.5, p.ground.y, 0.0});
    ASSERT_TRUE(expected);
    EXPECT_NEAR(p.pixel.v, expected->v, 1.0) << p.pixel.u;
    EXPECT_DOUBLE_EQ(p.pixel.u - std::floor(p.pixel.u), 0.5);
  }
  EXPECT_EQ(s.stats.rejected_width, 0);
  EXPECT_EQ(s.stats.rejected_edge, 0);
}

TEST(ScanPoints, HandComputedRowForALevelCamera) {
  // Camera 0.5 m up at the pivot, looking level: a line 2 m ahead is at v = cy + fy·0.25.
  Camera cam;
  cam.mount = {0.5, 0.0, 0.0};
  cam.head = {0.0, 0.0};
  testing::Scene scene;
  scene.lines = {{{2.0, -3.0}, {2.0, 3.0}}};
  ScanParams params;
  params.horizontal = false;
  const Scanned s = scan(scene, cam, params);
  ASSERT_FALSE(s.points.empty());
  const double v = 240.0 + cam.k.fy * 0.25;
  for (const CandidatePoint& p : s.points) {
    EXPECT_NEAR(p.pixel.v, v, 1.0);
    EXPECT_NEAR(p.ground.x, 2.0, 0.02);
    EXPECT_NEAR(p.ground.y, -(p.pixel.u - 320.0) / cam.k.fx * 2.0, 0.01);  // y left, u right
  }
}

TEST(ScanPoints, LinesRunningAwayAreFoundByHorizontalScans) {
  Camera cam;
  testing::Scene scene;
  scene.lines = {{{0.5, 0.3}, {6.0, 0.3}}};
  const Scanned s = scan(scene, cam);
  int horizontal = 0;
  const auto pose = cam.pose();
  for (const CandidatePoint& p : s.points) {
    EXPECT_NEAR(p.ground.y, 0.3, 0.03 + 0.01 * p.ground.x);
    if (p.direction != ScanDirection::kHorizontal) continue;
    ++horizontal;
    const auto expected = hal::project(cam.k, pose, {p.ground.x, 0.3, 0.0});
    ASSERT_TRUE(expected);
    EXPECT_NEAR(p.pixel.u, expected->u, 1.0) << p.pixel.v;
  }
  EXPECT_GT(horizontal, 150);  // about one per scanned row
}

TEST(ScanPoints, WhiteBlobsTooWideForALineAreRejected) {
  Camera cam;
  testing::Scene scene;
  scene.blobs = {{{1.2, -0.4}, {1.6, 0.4}}};  // a robot's white feet: 40 cm deep
  ScanParams params;
  params.horizontal = false;
  const Scanned s = scan(scene, cam, params);
  // Its interior is refused; what is left are the thin triangles where vertical scans clip its
  // front corners (a known limit of a per-run width test: too few and too short for a line).
  EXPECT_GT(s.stats.rejected_width, 100);
  EXPECT_LT(s.points.size(), 30U);
  for (const CandidatePoint& p : s.points) {
    EXPECT_NEAR(std::abs(p.ground.y), 0.4, 0.04);
    EXPECT_LT(p.ground.x, 1.3);
  }
}

TEST(ScanPoints, EdgeThresholdRefusesFaintRuns) {
  Camera cam;
  testing::Scene scene;
  scene.lines = {{{1.5, -3.0}, {1.5, 3.0}}};
  ScanParams params;
  params.horizontal = false;
  params.edge_threshold = 200;  // white minus green is ~125 in Y
  const Scanned s = scan(scene, cam, params);
  EXPECT_TRUE(s.points.empty());
  EXPECT_EQ(s.stats.rejected_edge, 320);
}

TEST(ScanPoints, CoarserGridStillFindsTheLine) {
  Camera cam;
  testing::Scene scene;
  scene.lines = {{{1.5, -3.0}, {1.5, 3.0}}};
  ScanParams params;
  params.horizontal = false;
  params.stride = 8;
  const Scanned s = scan(scene, cam, params, 2);
  EXPECT_EQ(s.points.size(), 80U);
  for (const CandidatePoint& p : s.points) EXPECT_NEAR(p.ground.x, 1.5, 0.04);
}

TEST(ScanPoints, BufferCountsWhatDoesNotFit) {
  CandidateBuffer b(2);
  EXPECT_TRUE(b.push({}));
  EXPECT_TRUE(b.push({}));
  EXPECT_FALSE(b.push({}));
  EXPECT_EQ(b.size(), 2U);
  EXPECT_EQ(b.dropped(), 1U);
  b.clear();
  EXPECT_EQ(b.size(), 0U);
  EXPECT_EQ(b.dropped(), 0U);
}

}  // namespace
}  // namespace ringlet::vision
