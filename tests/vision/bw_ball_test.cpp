// The black-and-white ball's candidates and the robots' foot points against the camera model:
// the expected radius is fx·R/depth, a rendered SPL ball yields a candidate at its projected centre
// with that radius, and a robot-shaped column standing on the field is found at its foot point.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ringlet/vision/bw_ball.hpp"
#include "ringlet/vision/horizon.hpp"
#include "ringlet/vision/messages.hpp"
#include "ringlet/vision/pipeline.hpp"
#include "ringlet/vision/robots.hpp"
#include "synthetic_field.hpp"

namespace ringlet::vision {
namespace {

using testing::Camera;

TEST(BwBall, ExpectedRadiusIsFocalLengthTimesRadiusOverDepth) {
  Camera cam;
  const hal::CameraPose pose = cam.pose();
  BwBallDetector d(BwBallParams{});
  for (const double x : {0.8, 1.5, 3.0, 5.0}) {
    const hal::Vec3 centre{x, 0.3, 0.05};
    const auto px = hal::project(cam.k, pose, centre);
    ASSERT_TRUE(px.has_value());
    hal::RobotPoint ground{};
    const double r = d.expected_radius_px(cam.k, pose, *px, &ground);
    const double depth = std::hypot(centre.x - pose.position.x, centre.y - pose.position.y, centre.z - pose.position.z);
    EXPECT_NEAR(r, cam.k.fx * 0.05 / depth, 1e-6 * r);
    EXPECT_NEAR(ground.x, x, 1e-6);
    EXPECT_NEAR(ground.y, 0.3, 1e-6);
  }
  // Above the horizon: no ball plane, no radius.
  EXPECT_EQ(d.expected_radius_px(cam.k, pose, {320, 0}), 0.0);
}

// BallPlane's closed form (the rotation's bottom row, |ray| = |n|) against the ray through the
// camera's rotation, on tilted bodies and turned heads where every entry of the rotation counts.
TEST(BwBall, TheBallPlaneGivesTheRaysRadiusAndGroundPoint) {
  Camera cam;
  const double R = BwBallParams{}.radius_m;
  int compared = 0;
  for (const hal::BodyTilt body : {hal::BodyTilt{}, hal::BodyTilt{0.09, -0.05}, hal::BodyTilt{-0.03, 0.12}}) {
    for (const hal::HeadJoints head : {hal::HeadJoints{0.0, 0.35}, hal::HeadJoints{0.7, 0.1}, hal::HeadJoints{-1.2, 0.45}}) {
      const hal::CameraPose pose = hal::CameraPose::from_body(cam.mount, body, head);
      const BallPlane plane(cam.k, pose, R);
      for (int v = 0; v < cam.k.height; v += 37) {
        for (int u = 0; u < cam.k.width; u += 41) {
          const hal::Pixel px{u + 0.5, v + 0.5};
          const hal::Vec3 ray = hal::pixel_ray(cam.k, pose, px);
          hal::RobotPoint g{};
          const bool meets = plane.ground(px, g);
          ASSERT_EQ(meets, ray.z < -1e-12) << u << "," << v;
          if (!meets) {
            EXPECT_EQ(plane.radius_px(px), 0.0);
            continue;
          }
          const double t = (R - pose.position.z) / ray.z;
          const double depth = t * std::sqrt(ray.x * ray.x + ray.y * ray.y + ray.z * ray.z);
          EXPECT_NEAR(plane.radius_px(px), cam.k.fx * R / depth, 1e-9 * cam.k.fx * R / depth);
          EXPECT_NEAR(g.x, pose.position.x + t * ray.x, 1e-9 * std::max(1.0, std::abs(g.x)));
          EXPECT_NEAR(g.y, pose.position.y + t * ray.y, 1e-9 * std::max(1.0, std::abs(g.y)));
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, 500);
}

// Renders `scene` (YUYV), classifies it with the default table and runs the detector unverified
// at ball stride 4.
void detect_unverified(const testing::Scene& scene, const Camera& cam, BwBallDetector& d, BallList& out) {
  const hal::CameraPose pose = cam.pose();
  const auto frame = testing::render(scene, cam, hal::PixelFormat::kYuyv);
  ClassImage classes(cam.k.width, cam.k.height);
  std::vector<int> rows(static_cast<std::size_t>(cam.k.width));
  const int horizon = horizon_rows(cam.k, pose, 2, rows);
  ASSERT_TRUE(classes.classify(frame.view, ColourTable::from_thresholds({}), horizon, 1));
  d.detect(classes, frame.view, cam.k, pose, 4, nullptr, 0, {}, out);
}

TEST(BwBall, RenderedBallGivesACandidateOfTheRightSize) {
  Camera cam;
  const hal::CameraPose pose = cam.pose();
  for (const hal::RobotPoint at : {hal::RobotPoint{0.9, 0.1}, hal::RobotPoint{1.6, -0.3}, hal::RobotPoint{3.0, 0.4}}) {
    testing::Scene scene = testing::field_scene();
    scene.ball = at;
    scene.ball_black_white = true;
    BwBallDetector d(BwBallParams{});
    BallList out;
    ASSERT_NO_FATAL_FAILURE(detect_unverified(scene, cam, d, out));
    const auto truth = hal::project(cam.k, pose, {at.x, at.y, 0.05});
    ASSERT_TRUE(truth.has_value());
    const double r_true = d.expected_radius_px(cam.k, pose, *truth);
    bool found = false;
    for (const BallCandidate& c : d.candidates()) {
      if (std::hypot(c.centre.u - truth->u, c.centre.v - truth->v) <= 0.5 * r_true + 2.0) {
        found = true;
        EXPECT_NEAR(c.radius, r_true, 0.15 * r_true);
      }
    }
    EXPECT_TRUE(found) << "ball at " << at.x << ", " << at.y << ": " << d.candidates().size() << " candidates";
    // Unverified: reported with a low confidence.
    ASSERT_GT(out.count, 0U);
    EXPECT_FALSE(out.balls[0].verified);
    EXPECT_LE(out.balls[0].confidence, 0.3);
  }
}

// A white patch of a ball's size lying on the carpet and the black-and-white ball: both are round
// non-field blobs of the right size, but only the ball has black patches inside, so it ranks first
// (the unverified report is the ball), and its outline puts the centre within a quarter radius.
TEST(BwBall, BlackPatchesRankTheBallAboveAPlainWhiteBlob) {
  Camera cam;
  const hal::CameraPose pose = cam.pose();
  testing::Scene scene = testing::field_scene();
  scene.ball = hal::RobotPoint{1.6, -0.3};
  scene.ball_black_white = true;
  scene.blobs = {{{1.0, 0.25}, {1.3, 0.37}}};  // deep enough to look square from the camera
  BwBallDetector d(BwBallParams{});
  BallList out;
  ASSERT_NO_FATAL_FAILURE(detect_unverified(scene, cam, d, out));
  const auto ball = hal::project(cam.k, pose, {1.6, -0.3, 0.05});
  const auto blob = hal::project(cam.k, pose, {1.15, 0.31, 0.0});
  ASSERT_TRUE(ball.has_value() && blob.has_value());
  const double r = d.expected_radius_px(cam.k, pose, *ball);
  const auto near = [&](const BallCandidate& c, const hal::Pixel& p, double within) {
    return std::hypot(c.centre.u - p.u, c.centre.v - p.v) <= within;
  };
  ASSERT_GE(d.candidates().size(), 2U);
  bool blob_proposed = false;
  for (const BallCandidate& c : d.candidates()) blob_proposed = blob_proposed || near(c, *blob, r);
  EXPECT_TRUE(blob_proposed) << "the white patch is a candidate too (the contrast only ranks it); blob at " << blob->u
                             << ", " << blob->v << "; first candidate at " << d.candidates()[0].centre.u << ", "
                             << d.candidates()[0].centre.v << "; " << d.candidates().size() << " candidates";
  const BallCandidate& best = d.candidates()[0];
  EXPECT_TRUE(near(best, *ball, 0.25 * r)) << "best at " << best.centre.u << ", " << best.centre.v << ", ball at "
                                           << ball->u << ", " << ball->v << " r " << r;
  EXPECT_GT(best.contrast, 0.5);
  EXPECT_GT(best.roundness, 0.5);
  ASSERT_GT(out.count, 0U);
  EXPECT_NEAR(out.balls[0].centre.u, ball->u, 0.25 * r);
}

// A ball half cut off by the image's left, right or bottom edge (its centre on the edge: the least
// an expected ball shows) is proposed at its true centre, within the evaluation's match radius of
// half its radius: the middle of the part seen lies half a radius off, so the candidate is placed a
// radius inside the part seen. (Before, the bottom case had no candidate within that radius.)
TEST(BwBall, ABallCutByTheImageEdgeIsCentredARadiusInside) {
  Camera cam;
  const hal::CameraPose pose = cam.pose();
  // The ground point at distance x whose ball centre projects to column u (bisection on y), or
  // straight ahead, the distance whose ball centre projects to row v.
  const auto at_column = [&](double x, double u) {
    double lo = -3.0, hi = 3.0;  // y left positive: u falls as y grows
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      const auto px = hal::project(cam.k, pose, {x, mid, 0.05});
      (px.has_value() && px->u > u ? lo : hi) = mid;
    }
    return hal::RobotPoint{x, 0.5 * (lo + hi)};
  };
  const auto at_row = [&](double v) {
    double lo = 0.2, hi = 3.0;  // v falls as x grows
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      const auto px = hal::project(cam.k, pose, {mid, 0.0, 0.05});
      (px.has_value() && px->v > v ? lo : hi) = mid;
    }
    return hal::RobotPoint{0.5 * (lo + hi), 0.0};
  };
  const double w = cam.k.width, h = cam.k.height;
  const struct {
    const char* edge;
    hal::RobotPoint at;
  } cases[] = {{"left", at_column(1.0, 0.0)}, {"right", at_column(1.0, w)}, {"bottom", at_row(h)}};
  for (const auto& c : cases) {
    testing::Scene scene = testing::field_scene();
    scene.ball = c.at;
    scene.ball_black_white = true;
    BwBallDetector d(BwBallParams{});
    BallList out;
    ASSERT_NO_FATAL_FAILURE(detect_unverified(scene, cam, d, out));
    const auto truth = hal::project(cam.k, pose, {c.at.x, c.at.y, 0.05});
    ASSERT_TRUE(truth.has_value());
    const double r = d.expected_radius_px(cam.k, pose, *truth);
    double nearest = 1e9;
    for (const BallCandidate& cand : d.candidates()) {
      nearest = std::min(nearest, std::hypot(cand.centre.u - truth->u, cand.centre.v - truth->v));
    }
    EXPECT_LE(nearest, 0.5 * r) << c.edge << " edge: ball at " << truth->u << ", " << truth->v << " r " << r << ", "
                                << d.candidates().size() << " candidates";
  }
}

// A robot drawn as a white column in the image, standing at a ground point: its foot row from the
// camera model, its height the projected 0.574 m. `half_width`: the column's half width as a share
// of that height (a NAO: 0.25); 0: the white reaches across the whole picture.
struct Column {
  RobotList out;
  hal::Pixel foot;
  double height = 0.0;
  hal::RobotPoint at{1.5, 0.2};
};

// What is painted (grey 230, non-field) on the grey-100 field: a block `half_width` robot heights
// either side of the foot, up to a robot's height; optionally field between the legs (a gap
// `legs_gap` heights wide up to a quarter height) and a ball-sized block `ball_gap` heights below
// the foot.
struct ColumnScene {
  double half_width = 0.25;
  double legs_gap = 0.0;
  double ball_gap = 0.0;
  double body_gap = 0.0;  // a field stripe this many heights tall across the body, 0.3 h above the foot
  hal::RobotPoint second{};  // another robot (ground point, robot frame) drawn first, so behind; 0: none
};

Column detect_column(const ColumnScene& scene_spec);
Column detect_column(double half_width) { return detect_column(ColumnScene{half_width, 0.0, 0.0, 0.0, {}}); }

// Classifies a Gray8 picture (grey 100 is field, 200 and brighter line: Gray8 classifies with
// U = V = 128) and runs the robot detector on it (columns every 4 px, no classifier).
bool detect_on_grey(const Camera& cam, std::vector<std::uint8_t>& img, RobotDetector& d, RobotList& out) {
  const hal::CameraPose pose = cam.pose();
  ColourThresholds t;
  t.field = {50, 150, 100, 156, 100, 156};
  t.line = {200, 255, 100, 156, 100, 156};
  t.ball = {0, 0, 0, 0, 0, 0};
  auto frame = testing::render(testing::Scene{}, cam, hal::PixelFormat::kGray8);
  hal::FrameView view = frame.view;
  view.data = img.data();
  view.stride = cam.k.width;
  view.format = hal::PixelFormat::kGray8;
  ClassImage classes(cam.k.width, cam.k.height);
  std::vector<int> rows(static_cast<std::size_t>(cam.k.width));
  if (!classes.classify(view, ColourTable::from_thresholds(t), horizon_rows(cam.k, pose, 2, rows), 1)) return false;
  d.detect(classes, view, cam.k, pose, 4, nullptr, 0, {}, out);
  return true;
}

// The column's foot pixel and image height where it stands (c.at); false when it does not project.
bool place_column(const Camera& cam, const RobotDetector& d, Column& c) {
  const hal::CameraPose pose = cam.pose();
  const auto foot = hal::project(cam.k, pose, {c.at.x, c.at.y, 0.0});
  EXPECT_TRUE(foot.has_value());
  if (!foot) return false;
  c.foot = *foot;
  c.height = d.expected_height_px(cam.k, pose, c.at);
  return true;
}

Column detect_column(const ColumnScene& scene_spec) {
  const double half_width = scene_spec.half_width;
  Camera cam;
  const hal::CameraPose pose = cam.pose();
  std::vector<std::uint8_t> img(static_cast<std::size_t>(cam.k.width * cam.k.height), 100);
  Column c;
  RobotDetector d(RobotParams{});
  if (!place_column(cam, d, c)) return c;
  const hal::Pixel* foot = &c.foot;
  const double h = c.height;
  const int x0 = half_width > 0.0 ? static_cast<int>(foot->u - half_width * h) : 0;
  const int x1 = half_width > 0.0 ? static_cast<int>(foot->u + half_width * h) : cam.k.width;
  const auto paint = [&](int left, int right, int top, int bottom, std::uint8_t value) {
    for (int y = std::max(0, top); y < std::min(bottom, cam.k.height); ++y) {
      for (int x = std::max(0, left); x < std::min(right, cam.k.width); ++x) {
        img[static_cast<std::size_t>(y * cam.k.width + x)] = value;
      }
    }
  };
  if (scene_spec.second.x > 0.0) {
    const auto f2 = hal::project(cam.k, pose, {scene_spec.second.x, scene_spec.second.y, 0.0});
    EXPECT_TRUE(f2.has_value());
    if (!f2) return c;
    const double h2 = d.expected_height_px(cam.k, pose, scene_spec.second);
    paint(static_cast<int>(f2->u - 0.25 * h2), static_cast<int>(f2->u + 0.25 * h2), static_cast<int>(f2->v - h2),
          static_cast<int>(f2->v), 230);
  }
  paint(x0, x1, static_cast<int>(foot->v - h), static_cast<int>(foot->v), 230);
  if (scene_spec.legs_gap > 0.0) {
    const double g = 0.5 * scene_spec.legs_gap * h;
    paint(static_cast<int>(foot->u - g), static_cast<int>(foot->u + g), static_cast<int>(foot->v - 0.25 * h),
          static_cast<int>(foot->v), 100);
  }
  if (scene_spec.body_gap > 0.0) {
    paint(x0, x1, static_cast<int>(foot->v - (0.3 + scene_spec.body_gap) * h), static_cast<int>(foot->v - 0.3 * h), 100);
  }
  if (scene_spec.ball_gap > 0.0) {
    const int top = static_cast<int>(foot->v + scene_spec.ball_gap * h);
    paint(static_cast<int>(foot->u - 0.1 * h), static_cast<int>(foot->u + 0.1 * h), top,
          top + static_cast<int>(0.2 * h), 230);
  }
  EXPECT_TRUE(detect_on_grey(cam, img, d, c.out));
  return c;
}

TEST(Robots, ColumnStandingOnTheFieldIsFoundAtItsFoot) {
  const Column c = detect_column(0.25);
  const double h = c.height;
  ASSERT_GT(h, 50.0);
  ASSERT_EQ(c.out.count, 1U);
  const RobotDetection& r = c.out.robots[0];
  EXPECT_FALSE(r.verified);
  EXPECT_NEAR(r.foot.u, c.foot.u, 4.0);
  EXPECT_NEAR(r.foot.v, c.foot.v, 2.0);
  // The lowest non-field row is the feet's near edge: the robot stands foot_depth_m beyond it.
  const double depth = RobotParams{}.foot_depth_m;
  EXPECT_NEAR(r.distance_m, std::hypot(c.at.x, c.at.y) + depth, 0.03 * std::hypot(c.at.x, c.at.y));
  EXPECT_NEAR(r.bearing_rad, std::atan2(c.at.y, c.at.x), 0.02);
  EXPECT_NEAR(r.height, h, 0.05 * h);
}

TEST(Robots, FieldBetweenTheLegsDoesNotSplitTheRobot) {
  // The columns between the legs end on the field a quarter height up: without joining, each leg
  // alone would be narrower than a robot's quarter width and dropped.
  const Column c = detect_column(ColumnScene{0.12, 0.1, 0.0, 0.0, {}});
  ASSERT_EQ(c.out.count, 1U);
  EXPECT_NEAR(c.out.robots[0].foot.u, c.foot.u, 6.0);
  EXPECT_NEAR(c.out.robots[0].foot.v, c.foot.v, 2.0);
}

TEST(Robots, ABallBeforeTheFeetIsNotTheFoot) {
  // A ball 0.2 robot heights tall lies before the feet. With 0.3 heights of field between, the gap
  // is too long to bridge; with 0.12 it is bridged, but what follows it is shorter than twice the
  // gap: not legs. Either way the run ends at the feet.
  for (const double gap : {0.3, 0.12}) {
    const Column c = detect_column(ColumnScene{0.25, 0.0, gap, 0.0, {}});
    ASSERT_GE(c.out.count, 1U) << gap;
    EXPECT_NEAR(c.out.robots[0].foot.v, c.foot.v, 2.0) << gap;
  }
}

// A near robot whose feet are below the image's bottom edge, with a shaded part of its shins
// passing for field a little above the edge. Its columns' run reaches the edge: the feet are at
// the edge or beyond, so the last row is the foot (the distance an upper bound), not the shaded
// gap, which had put near robots' feet 40-80 px too high on rendered frames.
TEST(Robots, FeetBelowTheImageEdgeAreAtTheEdgeNotAtAShadedGap) {
  Camera cam;
  const hal::CameraPose pose = cam.pose();
  RobotDetector d(RobotParams{});
  const int w = cam.k.width, rows = cam.k.height;
  const auto edge = hal::pixel_to_ground(cam.k, pose, {w / 2.0, rows - 0.5});
  ASSERT_TRUE(edge.has_value());
  const double h = d.expected_height_px(cam.k, pose, *edge);
  std::vector<std::uint8_t> img(static_cast<std::size_t>(w * rows), 100);
  const auto paint = [&](int top, int bottom, std::uint8_t value) {
    for (int y = std::max(0, top); y < std::min(bottom, rows); ++y)
      for (int x = static_cast<int>(w / 2.0 - 0.25 * h); x < static_cast<int>(w / 2.0 + 0.25 * h); ++x)
        img[static_cast<std::size_t>(y * w + x)] = value;
  };
  paint(static_cast<int>(rows - 0.9 * h), rows, 230);
  const int gap_top = static_cast<int>(rows - 0.2 * h), gap_bottom = static_cast<int>(rows - 0.12 * h);
  paint(gap_top, gap_bottom, 100);  // the shaded shins: 0.08 h of field, then 0.12 h of legs to the edge
  RobotList out;
  ASSERT_TRUE(detect_on_grey(cam, img, d, out));
  ASSERT_GE(out.count, 1U);
  EXPECT_GT(out.robots[0].foot.v, rows - 4.0) << "the foot at the edge, not at the gap (row " << gap_top << ")";
  EXPECT_LE(out.robots[0].distance_m, std::hypot(edge->x, edge->y) + RobotParams{}.foot_depth_m + 0.05);
}

TEST(Robots, ARobotJustBehindAnotherIsFoundToo) {
  // The second robot stands 0.7 m farther, mostly hidden: only 0.15 of the first robot's height
  // (of its image) shows beside it, on the right. Its columns end higher up, right beside the
  // first robot's, as the field between the legs would, all within the reach that joins legs.
  // Once the first robot ends, they are a candidate of their own.
  Camera cam;
  const hal::CameraPose pose = cam.pose();
  const RobotDetector d(RobotParams{});
  const hal::RobotPoint first{1.5, 0.2};
  const auto f1 = hal::project(cam.k, pose, {first.x, first.y, 0.0});
  ASSERT_TRUE(f1.has_value());
  const double h1 = d.expected_height_px(cam.k, pose, first);
  hal::RobotPoint second{2.2, 0.2};
  for (; second.y > -1.0; second.y -= 0.005) {  // to the right until 0.15 h1 of it shows
    const auto f2 = hal::project(cam.k, pose, {second.x, second.y, 0.0});
    ASSERT_TRUE(f2.has_value());
    if (f2->u + 0.25 * d.expected_height_px(cam.k, pose, second) - (f1->u + 0.25 * h1) >= 0.15 * h1) break;
  }
  const Column c = detect_column(ColumnScene{0.25, 0.0, 0.0, 0.0, second});
  ASSERT_EQ(c.out.count, 2U);
  const RobotDetection& near = c.out.robots[0];  // nearest first
  const RobotDetection& far = c.out.robots[1];
  EXPECT_NEAR(near.foot.v, c.foot.v, 2.0);
  EXPECT_LT(far.foot.v, near.foot.v - 20.0);
  EXPECT_GT(far.foot.u, near.foot.u);
}

TEST(Robots, WhenTheListIsFullTheFarthestGiveWay) {
  // 18 narrow far "robots" fill the 16 places first, then 5 nearer ones come (further right):
  // every nearer one must be kept, the farthest giving way.
  Camera cam;
  const hal::CameraPose pose = cam.pose();
  const RobotDetector probe(RobotParams{});
  const auto height_at_row = [&](int v) {
    const auto g = hal::pixel_to_ground(cam.k, pose, {320.0, v + 0.5});
    return g ? probe.expected_height_px(cam.k, pose, *g) : 0.0;
  };
  int far_row = 0;
  while (far_row < cam.k.height && height_at_row(far_row) < 40.0) ++far_row;
  ASSERT_LT(far_row + 60, cam.k.height);
  std::vector<std::uint8_t> img(static_cast<std::size_t>(cam.k.width * cam.k.height), 100);
  std::vector<int> near_rows;
  // Far ones 8 px wide every 24 px; nearer ones (4 rows lower each) 16 px wide every 40 px: wide
  // enough for their distance, too far apart to join.
  for (int b = 0; b < 23; ++b) {
    const bool near = b >= 18;
    const int foot = near ? far_row + 4 * (b - 17) : far_row;
    if (near) near_rows.push_back(foot);
    const int left = near ? 432 + 40 * (b - 18) : 24 * b;
    const int top = std::max(0, foot - static_cast<int>(height_at_row(foot)));
    for (int y = top; y < foot; ++y) {
      for (int x = left; x < left + (near ? 16 : 8); ++x) img[static_cast<std::size_t>(y * cam.k.width + x)] = 230;
    }
  }
  RobotDetector d(RobotParams{});
  RobotList out;
  ASSERT_TRUE(detect_on_grey(cam, img, d, out));
  ASSERT_EQ(d.candidates().size(), kMaxRobotCandidates);
  for (const int row : near_rows) {
    bool kept = false;
    for (const RobotCandidate& c : d.candidates()) kept = kept || std::abs(c.foot_row - row) <= 2;
    EXPECT_TRUE(kept) << "the candidate standing at row " << row << " was dropped";
  }
  EXPECT_GE(d.candidates()[0].foot_row, near_rows.back() - 2) << "nearest first";
}

TEST(Robots, AShadedStripeAcrossTheBodyIsBridged) {
  // Grey parts in shade pass for carpet: a field stripe 0.05 heights tall across the body, the legs
  // going on 0.3 heights below it. Not bridged, the run above it (0.65 heights) would stand there.
  const Column c = detect_column(ColumnScene{0.25, 0.0, 0.0, 0.05, {}});
  ASSERT_GE(c.out.count, 1U);
  EXPECT_NEAR(c.out.robots[0].foot.v, c.foot.v, 2.0);
}

TEST(Robots, NonFieldAcrossTheWholeViewIsNoRobot) {
  // The floor beyond the carpet also "stands on the field", but it is many robots wide.
  const Column c = detect_column(0.0);
  ASSERT_GT(c.height, 50.0);
  EXPECT_EQ(c.out.count, 0U);
  EXPECT_EQ(c.out.candidates, 0);
}

// The carpet's edge: the floor beyond it (grey 170: neither field nor line) runs from the top of
// the picture down to a straight edge, `slope` px per px, or to a corner (`corner`: the edge rises
// to the picture's middle and falls again). A robot standing on the carpet `before` robot heights
// below the edge at its feet joins the edge's columns into one candidate far wider than a robot;
// its feet, below the edge interpolated from either side, make it a candidate of its own.
struct EdgeScene {
  double slope = 0.1;
  bool corner = false;
  bool robot = true;
  double before = 0.06;
};

Column detect_at_edge(const EdgeScene& e) {
  Camera cam;
  const int w = cam.k.width, rows = cam.k.height;
  std::vector<std::uint8_t> img(static_cast<std::size_t>(w * rows), 100);
  Column c;
  RobotDetector d(RobotParams{});
  if (!place_column(cam, d, c)) return c;
  const hal::Pixel* foot = &c.foot;
  const double h = c.height;
  const double at_feet = foot->v - e.before * h;  // the edge's row at the robot's feet
  for (int x = 0; x < w; ++x) {
    const double edge = e.corner ? at_feet - e.slope * (w / 2.0 - std::abs(x - w / 2.0)) + e.slope * (w / 2.0 - std::abs(foot->u - w / 2.0))
                                 : at_feet + e.slope * (x - foot->u);
    for (int y = 0; y < std::min(rows, static_cast<int>(edge)); ++y) img[static_cast<std::size_t>(y * w + x)] = 170;
  }
  if (e.robot) {
    for (int y = std::max(0, static_cast<int>(foot->v - h)); y < static_cast<int>(foot->v); ++y) {
      for (int x = static_cast<int>(foot->u - 0.25 * h); x < static_cast<int>(foot->u + 0.25 * h); ++x) {
        img[static_cast<std::size_t>(y * w + x)] = 230;
      }
    }
  }
  EXPECT_TRUE(detect_on_grey(cam, img, d, c.out));
  return c;
}

TEST(Robots, ARobotBeforeTheCarpetsEdgeIsFoundAtItsFeet) {
  for (const double slope : {0.0, 0.1, -0.15}) {
    for (const bool corner : {false, true}) {
      // The carpet is convex, so seen from on it a corner lies farther than its sides: a peak,
      // never a valley (a negative slope with a corner).
      if (corner && slope <= 0.0) continue;
      const Column c = detect_at_edge({slope, corner, true, 0.06});
      ASSERT_GT(c.height, 50.0);
      // The robot, at its feet and a robot wide. Pieces of the edge beside it are candidates too
      // (nearer ones first where the edge slopes down); the classifier rejects them, here there
      // is none.
      const std::string what = "slope " + std::to_string(slope) + (corner ? " corner" : "");
      const RobotDetection* at_feet = nullptr;
      for (std::size_t q = 0; q < c.out.count; ++q) {
        const RobotDetection& r = c.out.robots[q];
        if (std::abs(r.foot.u - c.foot.u) <= 0.06 * c.height && std::abs(r.foot.v - c.foot.v) <= 2.0) at_feet = &r;
      }
      ASSERT_NE(at_feet, nullptr) << what << ": " << c.out.count << " detections, none at the feet";
      EXPECT_NEAR(at_feet->width, 0.31 / 0.574 * c.height, 0.1 * c.height) << what;
    }
  }
}

TEST(Robots, TheCarpetsEdgeAloneIsNoRobot) {
  // Straight or with a corner (seen from inside, the corner lies farther: higher up), and with
  // feet standing too little before it to tell them from the edge.
  for (const bool corner : {false, true}) {
    const Column c = detect_at_edge({0.12, corner, false, 0.06});
    EXPECT_EQ(c.out.count, 0U) << (corner ? "corner" : "straight");
  }
  const Column c = detect_at_edge({0.1, false, true, 0.01});
  EXPECT_EQ(c.out.count, 0U) << "feet 1 % of a robot's height below the edge are the edge";
}

// The window placements the trainer and the detectors share.
TEST(HogWindows, BallAndRobotWindowsFollowTheParameters) {
  const WindowPlacement b = ball_window(BwBallParams{}, HogParams::ball(), {100, 80}, 10);
  EXPECT_DOUBLE_EQ(b.scale, 1.6 * 20 / 32);
  EXPECT_DOUBLE_EQ(b.left, 100 - 16);
  EXPECT_DOUBLE_EQ(b.top, 80 - 16);
  const WindowPlacement r = robot_window(RobotParams{}, HogParams::robot(), {200, 300}, 112);
  EXPECT_DOUBLE_EQ(r.scale, 2.0);                 // 112 × 64/56 = 128 px high → 2 px per window px
  EXPECT_DOUBLE_EQ(r.top, 300 - 60 * 2.0);        // the foot at window row 60
  EXPECT_DOUBLE_EQ(r.left, 200 - 16 * 2.0);
}

}  // namespace
}  // namespace ringlet::vision

namespace ringlet::vision {
namespace {

// RobotDetections carries the pipeline's robots and survives the text round trip.
TEST(Robots, WhiteboardMessageHoldsTheRobots) {
  static_assert(std::tuple_size_v<decltype(wb::RobotDetections{}.foot_x)> == kMaxRobots);
  VisionResult r;
  r.sequence = 9;
  r.robots.count = 2;
  r.robots.robots[0].ground = {1.5, 0.2};
  r.robots.robots[0].distance_m = std::hypot(1.5, 0.2);
  r.robots.robots[0].bearing_rad = std::atan2(0.2, 1.5);
  r.robots.robots[0].verified = true;
  r.robots.robots[0].confidence = 0.8;
  r.robots.robots[1].ground = {2.5, -0.7};
  const wb::RobotDetections m = to_robot_detections(r);
  EXPECT_EQ(m.sequence, 9U);
  EXPECT_EQ(m.count, 2);
  EXPECT_EQ(m.foot_x[0], 1.5);
  EXPECT_EQ(m.foot_y[1], -0.7);
  EXPECT_EQ(m.verified[0], 1);
  EXPECT_EQ(m.verified[1], 0);
  EXPECT_EQ(m.confidence[0], 0.8);
  const auto back = wb::RobotDetections::from_string(m.description());
  ASSERT_TRUE(back.has_value()) << back.error();
  EXPECT_EQ(back.value(), m);
}

}  // namespace
}  // namespace ringlet::vision
