// Scan-line candidates on synthetic frames: run centres land on the painted line's centre (within
// 1 px of its projection), white blobs too wide for a line are refused, lines running down the
// image are found by the horizontal scans.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
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

// A camera's optics soften the paint's edges: a 3×3 box blur of the luminance (YUYV: every other
// byte), twice.
void soften(testing::Frame& f) {
  const int w = f.view.width, h = f.view.height;
  std::vector<std::uint8_t> y(static_cast<std::size_t>(w * h));
  for (int pass = 0; pass < 2; ++pass) {
    for (int i = 0; i < w * h; ++i) y[static_cast<std::size_t>(i)] = f.bytes[2 * static_cast<std::size_t>(i)];
    for (int r = 1; r + 1 < h; ++r) {
      for (int c = 1; c + 1 < w; ++c) {
        int sum = 0;
        for (int dr = -1; dr <= 1; ++dr) {
          for (int dc = -1; dc <= 1; ++dc) sum += y[static_cast<std::size_t>((r + dr) * w + c + dc)];
        }
        f.bytes[2 * static_cast<std::size_t>(r * w + c)] = static_cast<std::uint8_t>(sum / 9);
      }
    }
  }
}

Scanned scan(const testing::Scene& scene, const Camera& cam, ScanParams params = {}, int step = 1, bool soft = false) {
  auto f = testing::render(scene, cam, hal::PixelFormat::kYuyv);
  if (soft) soften(f);
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

// Each candidate carries its paint's direction from the run's edges: a ground direction written
// in the vectors one pixel along and across the paint (h = α·along + β·across runs at atan|β/α|
// to it in the picture). The line's own ground direction must come out along the paint, for lines
// across the view, running away and slanted.
TEST(ScanPoints, EachCandidateKnowsWhichWayItsPaintRuns) {
  Camera cam;
  for (const auto& [a, b] : {std::pair{hal::RobotPoint{1.5, -3.0}, hal::RobotPoint{1.5, 3.0}},
                             std::pair{hal::RobotPoint{0.5, 0.3}, hal::RobotPoint{6.0, 0.3}},
                             std::pair{hal::RobotPoint{0.8, -1.5}, hal::RobotPoint{3.0, 1.0}}}) {
    testing::Scene scene;
    scene.lines = {{a, b}};
    const Scanned s = scan(scene, cam, {}, 1, true);
    ASSERT_GT(s.points.size(), 50U);
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    const double hx = (b.x - a.x) / len, hy = (b.y - a.y) / len;
    // tan of the picture angle between ground direction (dx, dy) and the candidate's paint.
    const auto picture_tan = [](const CandidatePoint& p, double dx, double dy) {
      const hal::RobotPoint& u = p.ground_along;
      const hal::RobotPoint& v = p.ground_across;
      return std::abs(u.x * dy - u.y * dx) / std::abs(dx * v.y - dy * v.x);
    };
    // Without the blur, the synthetic paint's hard pixel staircases bias a Sobel's angle by up to
    // 12°.
    std::vector<double> errors_deg;
    for (const CandidatePoint& p : s.points) {
      if (p.ground_along.x == 0.0 && p.ground_along.y == 0.0) continue;
      errors_deg.push_back(std::atan(picture_tan(p, hx, hy)) * 180.0 / std::numbers::pi);
    }
    ASSERT_GT(errors_deg.size(), s.points.size() * 9 / 10) << "directions known";
    std::sort(errors_deg.begin(), errors_deg.end());
    EXPECT_LT(errors_deg[errors_deg.size() / 2], 4.0) << a.x << "," << a.y << ": median";
    EXPECT_LT(errors_deg[errors_deg.size() * 9 / 10], 6.0) << a.x << "," << a.y << ": 90th percentile";
  }
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

// Sunlit carpet near white (val2_s101 frame 1385: carpet Y 230–236 U 50, the paint Y 254 U 124):
// the paint is only 18 brighter, less than edge_threshold, but far less saturated. The chroma
// term finds it; luminance alone found nothing.
TEST(ScanPoints, PaintOnSunlitCarpetIsFoundByItsChroma) {
  Camera cam;
  testing::Scene scene;
  scene.lines = {{{1.5, -3.0}, {1.5, 3.0}}};
  testing::Frame f = testing::render(scene, cam, hal::PixelFormat::kYuyv);
  for (std::size_t i = 0; i + 3 < f.bytes.size(); i += 4) {  // Y0 U Y1 V
    const bool paint = f.bytes[i] > 150 || f.bytes[i + 2] > 150;
    for (const std::size_t y : {i, i + 2}) f.bytes[y] = f.bytes[y] > 150 ? 254 : 236;
    f.bytes[i + 1] = paint ? 124 : 50;
    f.bytes[i + 3] = paint ? 128 : 131;
  }
  ColourThresholds sunlit;
  sunlit.field = {200, 245, 30, 70, 120, 140};
  sunlit.line = {246, 255, 110, 140, 110, 140};
  const ColourTable table = ColourTable::from_thresholds(sunlit);
  std::vector<int> rows(640);
  const int first = horizon_rows(cam.k, cam.pose(), 2, rows);
  ClassImage classes(640, 480);
  ASSERT_TRUE(classes.classify(f.view, table, first, 1));
  const auto candidates = [&](double chroma_weight) {
    ScanParams params;
    params.horizontal = false;
    params.edge_chroma_weight = chroma_weight;
    CandidateBuffer out(4096);
    LineScanner scanner(640);
    const ScanStats stats = scanner.scan(classes, f.view, cam.k, cam.pose(), rows, params, out);
    EXPECT_EQ(stats.runs, 320);
    return out.size();
  };
  EXPECT_EQ(candidates(ScanParams{}.edge_chroma_weight), 320U);
  EXPECT_EQ(candidates(0.0), 0U) << "Y alone: 254 − 236 < 24";
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
