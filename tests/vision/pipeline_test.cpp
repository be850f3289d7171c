// The whole pipeline on a synthetic field, the budget (a fake stopwatch that runs out after N
// reads: trials are cut and reported, later stages skipped) and the degrade levels.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ringlet/vision/messages.hpp"
#include "ringlet/vision/pipeline.hpp"
#include "ringlet/whiteboard/messages.hpp"
#include "synthetic_field.hpp"

namespace ringlet::vision {
namespace {

using testing::Camera;

/// Every read of the clock advances it by 1 µs: "N reads" is a budget of N µs.
class FakeStopwatch final : public hal::Stopwatch {
 public:
  [[nodiscard]] hal::Nanos wall_now() const noexcept override { return hal::Nanos{1000 * reads_++}; }
  [[nodiscard]] hal::Nanos cpu_now() const noexcept override { return wall_now(); }
  [[nodiscard]] long reads() const noexcept { return reads_; }

 private:
  mutable long reads_ = 0;
};

Deadline after_reads(const FakeStopwatch& w, long n) { return Deadline{&w, hal::Nanos{1000 * n}, false}; }

VisionPipeline make() { return VisionPipeline(VisionConfig{}, ColourTable::from_thresholds({})); }

bool matches(const FieldLine& f, hal::RobotPoint a, hal::RobotPoint b, double tol) {
  const auto off = [&](hal::RobotPoint p) {
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    return std::abs((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / len;
  };
  return off(f.ground_start) < tol && off(f.ground_end) < tol;
}

TEST(Pipeline, FindsTheLinesTheCircleAndTheBall) {
  Camera cam;
  const auto frame = testing::render(testing::field_scene(), cam, hal::PixelFormat::kYuyv, 17);
  VisionPipeline p = make();
  const VisionResult& r = p.process(frame.view, cam.head);
  EXPECT_EQ(r.status, VisionStatus::kOk);
  EXPECT_EQ(r.sequence, 17U);
  EXPECT_GT(r.candidates, 200);
  int halfway = 0, touch = 0;
  for (std::size_t i = 0; i < r.line_count; ++i) {
    const FieldLine& f = r.lines[i];
    if (matches(f, {3.0, -3.0}, {3.0, 3.0}, 0.1)) {
      ++halfway;
    } else if (matches(f, {0.8, 1.2}, {6.0, 1.2}, 0.1)) {
      ++touch;
    } else {
      ADD_FAILURE() << "spurious line (" << f.ground_start.x << "," << f.ground_start.y << ")-(" << f.ground_end.x
                    << "," << f.ground_end.y << ") inliers " << f.inliers;
    }
  }
  EXPECT_GE(halfway, 1);
  EXPECT_GE(touch, 1);
  EXPECT_TRUE(r.circle.seen);
  if (r.circle.seen) {
    EXPECT_NEAR(r.circle.radius_m, 0.75, 0.1);
    EXPECT_NEAR(r.circle.centre.x, 3.0, 0.1);
    EXPECT_NEAR(r.circle.centre.y, 0.0, 0.1);
    EXPECT_GT(r.circle.confidence, 0.5);
    EXPECT_LE(r.circle.confidence, 1.0);
  }
  EXPECT_GT(r.circle_stats.trials_run, 0);
  ASSERT_TRUE(r.ball.seen);
  EXPECT_NEAR(r.ball.ground.x, 1.4, 0.05);
  EXPECT_NEAR(r.ball.ground.y, -0.4, 0.03);
  EXPECT_FALSE(r.cut.deadline_hit);
  EXPECT_EQ(r.cut.stages_skipped, 0);
}

// Rendered views of the centre circle alone, seen partially (the rest outside the picture), near
// and far, to the left and right: no straight line is ever reported, and the circle is found
// (centre within 10 cm) in the views that show enough of it.
TEST(Pipeline, PartlySeenCentreCircleGivesNoLines) {
  struct View {
    hal::RobotPoint centre;
    double yaw, pitch;
    bool expect_circle;
  };
  const View views[] = {
      {{1.3, 0.9}, 0.0, 0.35, true},     // near, its right part in the lower left of the picture
      {{1.3, -0.9}, 0.0, 0.35, true},    // mirrored
      {{0.9, 0.0}, 0.0, 0.45, true},     // near, looking down at its far half
      {{3.5, 1.4}, 0.0, 0.3, true},      // far, at the left edge
      {{4.5, 0.0}, 0.0, 0.2, true},      // far, whole
      {{2.0, 1.6}, -0.3, 0.35, false},   // a short arc at the left edge (≤ 60°: may or may not be found)
      {{2.5, -0.2}, 0.6, 0.35, false},   // head turned left: an arc at the right edge
  };
  VisionPipeline p = make();
  int i = 0;
  for (const View& v : views) {
    testing::Scene scene;
    scene.rings = {{v.centre, 0.75}};
    scene.noise = 6;
    Camera cam;
    cam.head = {v.yaw, v.pitch};
    const auto frame = testing::render(scene, cam, hal::PixelFormat::kYuyv, static_cast<std::uint64_t>(i));
    const VisionResult& r = p.process(frame.view, cam.head);
    EXPECT_EQ(r.line_count, 0U) << "view " << i << ": " << r.line_count << " lines, first ("
                                << r.lines[0].ground_start.x << "," << r.lines[0].ground_start.y << ")-("
                                << r.lines[0].ground_end.x << "," << r.lines[0].ground_end.y << ")";
    if (v.expect_circle) {
      EXPECT_TRUE(r.circle.seen) << "view " << i;
    }
    if (r.circle.seen) {
      EXPECT_LT(std::hypot(r.circle.centre.x - v.centre.x, r.circle.centre.y - v.centre.y), 0.10) << "view " << i;
    }
    ++i;
  }
}

TEST(Pipeline, SameFrameSameResult) {
  Camera cam;
  const auto frame = testing::render(testing::field_scene(), cam, hal::PixelFormat::kBgr8, 3);
  VisionPipeline a = make(), b = make();
  const VisionResult& ra = a.process(frame.view, cam.head);
  const VisionResult& rb = b.process(frame.view, cam.head);
  ASSERT_EQ(ra.line_count, rb.line_count);
  for (std::size_t i = 0; i < ra.line_count; ++i) {
    EXPECT_EQ(ra.lines[i].ground_start.x, rb.lines[i].ground_start.x);
    EXPECT_EQ(ra.lines[i].inliers, rb.lines[i].inliers);
  }
}

TEST(Pipeline, DeadlineCutsTrialsAndSaysSo) {
  Camera cam;
  const auto frame = testing::render(testing::field_scene(), cam, hal::PixelFormat::kYuyv);
  VisionPipeline p = make();
  // Unlimited first, counting the reads a full run makes.
  FakeStopwatch full_watch;
  const VisionResult full = p.process(frame.view, cam.head, after_reads(full_watch, 1L << 40));
  EXPECT_FALSE(full.cut.deadline_hit);
  EXPECT_EQ(full.cut.trials_skipped, 0);
  EXPECT_GT(full.ransac.trials_run, 30);
  EXPECT_EQ(full.stage_time[static_cast<std::size_t>(Stage::kRansac)].count() % 1000, 0);
  // Reads before RANSAC: start, 5 laps, 5 stage checks (classify, ball, scan, circle, RANSAC; no
  // robot model is installed, so the robot stage does not run) = 11, and one per centre circle
  // trial (40); then one per line trial. A budget of 11 + 40 + 12 reads lets exactly 12 line
  // trials run.
  EXPECT_EQ(full.circle_stats.trials_run, 40);
  FakeStopwatch watch;
  const VisionResult& cut = p.process(frame.view, cam.head, after_reads(watch, 11 + 40 + 12));
  EXPECT_TRUE(cut.cut.deadline_hit);
  EXPECT_TRUE(cut.cut.lines_not_extracted);
  EXPECT_EQ(cut.ransac.trials_run, 12);
  EXPECT_EQ(cut.cut.trials_skipped, 30 - 12);
  EXPECT_GT(cut.cut.points_left, 0);
  EXPECT_EQ(cut.cut.stages_skipped, 0);  // RANSAC started, it was cut short
  EXPECT_TRUE(cut.cut.lines_cut());
  EXPECT_FALSE(full.cut.lines_cut());
  EXPECT_TRUE(cut.ball.seen);            // the ball ran before
  EXPECT_LE(cut.line_count, 2U);         // the best of 12 trials is still used (maybe in pieces)
}

TEST(Pipeline, ExpiredDeadlineSkipsStages) {
  Camera cam;
  const auto frame = testing::render(testing::field_scene(), cam, hal::PixelFormat::kYuyv);
  VisionPipeline p = make();
  FakeStopwatch watch;
  const VisionResult& r = p.process(frame.view, cam.head, after_reads(watch, 0));
  EXPECT_TRUE(r.cut.deadline_hit);
  const auto bit = [](Stage s) { return 1U << static_cast<unsigned>(s); };
  EXPECT_EQ(r.cut.stages_skipped, bit(Stage::kClassify) | bit(Stage::kBall) | bit(Stage::kRobots) | bit(Stage::kScan) |
                                      bit(Stage::kCircle) | bit(Stage::kRansac));
  EXPECT_FALSE(r.cut.lines_not_extracted);
  EXPECT_TRUE(r.cut.lines_cut()) << "no line search at all is a cut one";
  EXPECT_FALSE(r.ball.seen);
  EXPECT_EQ(r.line_count, 0U);
}

TEST(Pipeline, DegradeLevelsDoLess) {
  Camera cam;
  const auto frame = testing::render(testing::field_scene(), cam, hal::PixelFormat::kYuyv);
  VisionPipeline p = make();
  const VisionResult r0 = p.process(frame.view, cam.head, {}, 0);
  const VisionResult r1 = p.process(frame.view, cam.head, {}, 1);
  const VisionResult r2 = p.process(frame.view, cam.head, {}, 2);
  const VisionResult r9 = p.process(frame.view, cam.head, {}, 9);
  EXPECT_EQ(r9.degrade_level, 2);
  EXPECT_GT(r0.candidates, r1.candidates);
  EXPECT_GT(r1.candidates, r2.candidates);
  EXPECT_GT(r0.ransac.trials_run, r1.ransac.trials_run);
  EXPECT_GT(r1.ransac.trials_run, r2.ransac.trials_run);
  EXPECT_EQ(r1.ransac.trials_run % 15, 0);
  EXPECT_EQ(r2.ransac.trials_run % 8, 0);
  // Still useful: the halfway line and the ball at every level.
  for (const VisionResult* r : {&r0, &r1, &r2}) {
    bool halfway = false;
    for (std::size_t i = 0; i < r->line_count; ++i) halfway |= matches(r->lines[i], {3.0, -3.0}, {3.0, 3.0}, 0.1);
    EXPECT_TRUE(halfway) << r->degrade_level;
    EXPECT_TRUE(r->ball.seen) << r->degrade_level;
  }
}

// A robot's legs look like a line running away from the camera: upright pieces lying inside a
// verified robot's box are dropped, nothing else is.
TEST(Pipeline, UprightPiecesInsideAVerifiedRobotAreItsLegs) {
  const auto piece = [](double u0, double v0, double u1, double v1) {
    FieldLine f;
    f.image_start = {u0, v0};
    f.image_end = {u1, v1};
    return f;
  };
  RobotList robots;
  robots.count = 2;
  robots.robots[0] = {100.0, 50.0, 60.0, 120.0, {}, {}, 0.0, 0.0, true, 1.0, 1.0};    // verified: u 100-160, v 50-170
  robots.robots[1] = {300.0, 50.0, 60.0, 120.0, {}, {}, 0.0, 0.0, false, 0.0, 0.0};  // a candidate the SVM refused
  std::array<FieldLine, kMaxLines> lines{};
  lines[0] = piece(120, 80, 125, 160);   // a leg: upright, inside the verified box
  lines[1] = piece(320, 80, 322, 160);   // upright, but the robot is not verified
  lines[2] = piece(105, 150, 155, 140);  // across the verified box: a line seen behind the legs
  lines[3] = piece(130, 100, 140, 240);  // upright, running out of the box
  lines[4] = piece(150, 60, 110, 165);   // inside, but slanted 21° from the vertical
  const std::size_t n = drop_robot_legs(lines, 5, robots, 0.35);
  ASSERT_EQ(n, 4U);
  EXPECT_DOUBLE_EQ(lines[0].image_start.u, 320.0) << "the others keep their order";
  EXPECT_DOUBLE_EQ(lines[1].image_start.u, 105.0);
  EXPECT_DOUBLE_EQ(lines[2].image_start.u, 130.0);
  EXPECT_DOUBLE_EQ(lines[3].image_start.u, 150.0);
  lines[0] = piece(120, 80, 125, 160);
  EXPECT_EQ(drop_robot_legs(lines, 1, robots, -1.0), 1U) << "a negative slant turns it off";
  EXPECT_EQ(drop_robot_legs(lines, 1, robots, 0.35), 0U);
}

// A goal post's or a leg's base lines up like a line running away; above its top end the band
// goes on up, above a painted line's end lies carpet.
TEST(Pipeline, UprightPiecesWhoseBandGoesOnUpAreStandingObjects) {
  std::vector<std::uint8_t> grey(640 * 480, 100);  // carpet
  const auto paint = [&](int u0, int u1, int v0, int v1) {
    for (int v = v0; v < v1; ++v) {
      for (int u = u0; u < u1; ++u) grey[static_cast<std::size_t>(v) * 640 + static_cast<std::size_t>(u)] = 200;
    }
  };
  paint(300, 306, 100, 400);  // a post: bright from row 100 down to its base
  paint(400, 405, 200, 300);  // a painted line's piece, ending at row 200
  paint(100, 300, 420, 425);  // a line across the picture
  hal::FrameView frame;
  frame.format = hal::PixelFormat::kGray8;
  frame.width = 640;
  frame.height = 480;
  frame.stride = 640;
  frame.data = grey.data();
  const auto piece = [](double u0, double v0, double u1, double v1) {
    FieldLine f;
    f.image_start = {u0, v0};
    f.image_end = {u1, v1};
    return f;
  };
  std::array<FieldLine, kMaxLines> lines{};
  lines[0] = piece(303, 390, 303, 250);  // on the post, its top end at row 250: the band goes on
  lines[1] = piece(402, 300, 402, 201);  // the line's piece, cut at its end: carpet above
  lines[2] = piece(100, 422, 299, 422);  // not upright
  lines[3] = piece(402, 201, 402, 300);  // the line's piece again, its ends the other way round
  const std::size_t n = drop_standing_objects(lines, 4, frame, 0.35, 18);
  ASSERT_EQ(n, 3U);
  EXPECT_DOUBLE_EQ(lines[0].image_start.u, 402.0) << "the others keep their order";
  EXPECT_DOUBLE_EQ(lines[1].image_start.u, 100.0);
  EXPECT_DOUBLE_EQ(lines[2].image_start.v, 201.0);
  lines[0] = piece(303, 250, 303, 390);  // the post with its ends the other way round
  EXPECT_EQ(drop_standing_objects(lines, 1, frame, 0.35, 18), 0U);
  lines[0] = piece(303, 250, 303, 390);
  EXPECT_EQ(drop_standing_objects(lines, 1, frame, 0.35, 0), 1U) << "reach 0 turns it off";
}

TEST(Pipeline, WrongFrameSizeIsRefused) {
  VisionPipeline p = make();
  std::vector<std::uint8_t> bytes(320 * 240 * 2);
  hal::FrameView f;
  f.width = 320;
  f.height = 240;
  f.stride = 640;
  f.data = bytes.data();
  EXPECT_EQ(p.process(f, hal::HeadJoints{}).status, VisionStatus::kBadFrame);
}

// The messages the firmware posts hold what the pipeline reports, and survive the text round trip.
TEST(Pipeline, MessagesHoldTheResult) {
  static_assert(std::tuple_size_v<decltype(wb::FieldLines{}.length)> == kMaxLines);
  Camera cam;
  const auto frame = testing::render(testing::field_scene(), cam, hal::PixelFormat::kYuyv, 42);
  VisionPipeline p = make();
  const VisionResult& r = p.process(frame.view, cam.head);
  ASSERT_GT(r.line_count, 0U);
  const wb::FieldLines m = to_field_lines(r);
  EXPECT_EQ(m.count, r.line_count);
  EXPECT_EQ(m.image_u0[0], r.lines[0].image_start.u);
  EXPECT_EQ(m.image_v1[0], r.lines[0].image_end.v);
  EXPECT_EQ(m.ground_y1[0], r.lines[0].ground_end.y);
  EXPECT_EQ(m.inliers[0], r.lines[0].inliers);
  EXPECT_EQ(m.circle_seen, r.circle.seen);
  const auto back = wb::FieldLines::from_string(m.description());
  ASSERT_TRUE(back.has_value()) << back.error();
  EXPECT_EQ(back.value(), m);
  // The marks (version 2): a cross in view is carried with its centre, orientation and confidence.
  static_assert(std::tuple_size_v<decltype(wb::FieldLines{}.mark_x)> == kMaxFieldMarks);
  testing::Scene cross = testing::field_scene();
  cross.lines.push_back({{1.2, 0.55}, {1.3, 0.55}});
  cross.lines.push_back({{1.25, 0.5}, {1.25, 0.6}});
  const auto cross_frame = testing::render(cross, cam, hal::PixelFormat::kYuyv, 43);
  const VisionResult& with_mark = p.process(cross_frame.view, cam.head);
  ASSERT_EQ(with_mark.marks.count, 1U);
  const wb::FieldLines mm = to_field_lines(with_mark);
  EXPECT_EQ(mm.mark_count, 1U);
  EXPECT_EQ(mm.mark_x[0], with_mark.marks.marks[0].centre.x);
  EXPECT_EQ(mm.mark_y[0], with_mark.marks.marks[0].centre.y);
  EXPECT_EQ(mm.mark_orientation[0], with_mark.marks.marks[0].orientation_rad);
  EXPECT_EQ(mm.mark_confidence[0], with_mark.marks.marks[0].confidence);
  EXPECT_NEAR(mm.mark_x[0], 1.25, 0.02);
  EXPECT_NEAR(mm.mark_y[0], 0.55, 0.02);
  const auto mark_back = wb::FieldLines::from_string(mm.description());
  ASSERT_TRUE(mark_back.has_value()) << mark_back.error();
  EXPECT_EQ(mark_back.value(), mm);
  const wb::BallBelief ball = to_ball_belief(r);
  EXPECT_FALSE(ball.simulated);
  EXPECT_EQ(ball.visible, r.ball.seen && r.ball.ground_valid);
}

}  // namespace
}  // namespace ringlet::vision
