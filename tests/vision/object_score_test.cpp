// The ball and robot scores of ringlet-vision-eval (object_score.hpp): the matching tolerances,
// one-to-one matching, what counts for recall, and the relative distance errors.
#include <gtest/gtest.h>

#include <vector>

#include "object_score.hpp"

namespace ringlet::vision::evaluate {
namespace {

TruthBall ball(double u, double v, double radius, double distance, double visible = 1.0, double in_image = 1.0) {
  TruthBall t;
  t.in_front = t.visible = true;
  t.u = u;
  t.v = v;
  t.radius_px = radius;
  t.distance_m = distance;
  t.visible_fraction = visible;
  t.in_image_fraction = in_image;
  return t;
}

TEST(BallScore, CentreWithinHalfTheRadiusOrFourPixels) {
  const std::vector<TruthBall> truth{ball(100, 100, 20, 2.0)};
  // 9.9 px off: inside half of 20 px.
  ObjectCounts c = score_balls(std::vector<FoundBall>{{109.9, 100, true, 2.2}}, truth);
  EXPECT_EQ(c.true_positives, 1U);
  EXPECT_EQ(c.recalled, 1U);
  EXPECT_NEAR(c.mean_error(), 0.1, 1e-12);
  // 10.5 px off: outside; a false positive and a miss.
  c = score_balls(std::vector<FoundBall>{{110.5, 100, true, 2.0}}, truth);
  EXPECT_EQ(c.true_positives, 0U);
  EXPECT_EQ(c.expected, 1U);
  EXPECT_EQ(c.recalled, 0U);
  EXPECT_DOUBLE_EQ(c.precision(), 0.0);
  // A small far ball: 4 px is the floor.
  c = score_balls(std::vector<FoundBall>{{103.5, 100, true, 4.0}}, std::vector<TruthBall>{ball(100, 100, 3, 4.5)});
  EXPECT_EQ(c.recalled, 1U);
}

TEST(BallScore, FarOrHiddenBallsAreDontCare) {
  const std::vector<TruthBall> truth{ball(100, 100, 6, 5.5), ball(300, 100, 20, 2.0, 0.6, 0.7)};
  // Neither is expected (beyond 5 m; 42 % visible), but detecting them is right.
  const ObjectCounts c = score_balls(std::vector<FoundBall>{{100, 100, true, 5.0}, {300, 100, true, 2.0}}, truth);
  EXPECT_EQ(c.expected, 0U);
  EXPECT_EQ(c.true_positives, 2U);
  EXPECT_DOUBLE_EQ(c.precision(), 1.0);
  EXPECT_EQ(c.errors, 0U);  // errors only over expected balls
}

TEST(BallScore, OneDetectionPerBall) {
  const std::vector<TruthBall> truth{ball(100, 100, 20, 2.0)};
  const ObjectCounts c = score_balls(std::vector<FoundBall>{{102, 100, true, 2.0}, {101, 100, true, 3.0}}, truth);
  EXPECT_EQ(c.detections, 2U);
  EXPECT_EQ(c.true_positives, 1U);
  EXPECT_DOUBLE_EQ(c.error_max, 0.5);  // the nearer detection (101) matched
}

TruthRobot robot(double foot_u, double foot_v, double width, double height, double distance) {
  TruthRobot t;
  t.in_front = t.visible = t.has_box = t.foot_projects = true;
  t.foot_u = foot_u;
  t.foot_v = foot_v;
  t.u0 = foot_u - width / 2;
  t.u1 = foot_u + width / 2;
  t.v0 = foot_v - height;
  t.v1 = foot_v;
  t.distance_m = distance;
  t.visible_fraction = 1.0;
  return t;
}

TEST(RobotScore, FootWithinHalfTheBoxWidth) {
  const std::vector<TruthRobot> truth{robot(320, 400, 60, 120, 2.0)};
  ObjectCounts c = score_robots(std::vector<FoundRobot>{{280, 282, 60, 120, 340, 402, 2.1}}, truth, 640, 480);
  EXPECT_EQ(c.recalled, 1U);
  EXPECT_NEAR(c.mean_error(), 0.05, 1e-12);
  // Foot 40 px off and boxes overlapping by IoU 0.2: no match.
  c = score_robots(std::vector<FoundRobot>{{330, 280, 60, 120, 360, 400, 2.0}}, truth, 640, 480);
  EXPECT_EQ(c.true_positives, 0U);
  EXPECT_DOUBLE_EQ(c.recall(), 0.0);
}

TEST(RobotScore, BoxOverlapMatchesAndFarRobotsAreDontCare) {
  // Foot 36 px too low (more than 30) but the boxes overlap by IoU 0.54.
  std::vector<TruthRobot> truth{robot(320, 400, 60, 120, 2.0)};
  ObjectCounts c = score_robots(std::vector<FoundRobot>{{290, 316, 60, 120, 320, 436, 2.0}}, truth, 640, 480);
  EXPECT_EQ(c.true_positives, 1U);
  // Beyond 3 m, or the foot below the image: not expected.
  truth = {robot(100, 300, 20, 40, 3.5), robot(320, 500, 60, 120, 1.0)};
  c = score_robots(std::vector<FoundRobot>{}, truth, 640, 480);
  EXPECT_EQ(c.expected, 0U);
  EXPECT_DOUBLE_EQ(c.recall(), 1.0);
}

// Each matched expected robot is recorded with its distances, the foot's offset and how it matched:
// the evaluation lists them so the largest errors can be looked at.
TEST(RobotScore, MatchesAreRecordedWithHowTheyMatched) {
  const std::vector<TruthRobot> truth{robot(320, 400, 60, 120, 2.0), robot(100, 300, 20, 40, 3.5)};
  std::vector<RobotMatch> matches;
  const ObjectCounts c = score_robots(std::vector<FoundRobot>{{290, 316, 60, 120, 320, 436, 2.5}, {90, 260, 20, 40, 100, 300, 3.4}},
                                      truth, 640, 480, {}, &matches);
  EXPECT_EQ(c.true_positives, 2U);
  ASSERT_EQ(matches.size(), 1U) << "the robot beyond 3 m matches but is not expected: not recorded";
  EXPECT_DOUBLE_EQ(matches[0].true_distance_m, 2.0);
  EXPECT_DOUBLE_EQ(matches[0].found_distance_m, 2.5);
  EXPECT_NEAR(matches[0].foot_offset_px, 36.0, 1e-9);
  EXPECT_FALSE(matches[0].by_foot) << "36 px is beyond half the box width: matched by overlap";
}

TEST(ObjectCounts, SumsAndKeepsTheMaximum) {
  ObjectCounts a, b;
  a.detections = 2;
  a.error_max = 0.3;
  b.detections = 1;
  b.error_max = 0.1;
  a += b;
  EXPECT_EQ(a.detections, 3U);
  EXPECT_DOUBLE_EQ(a.error_max, 0.3);
}

}  // namespace
}  // namespace ringlet::vision::evaluate
