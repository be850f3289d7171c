// The reactive layer (Powers & Balch §III-A) on hand-computed cases: arc geometry, each of the
// five behaviours' votes and speed limits, and the arbiter's choice.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ringlet/behaviour/reactive/voting.hpp"

namespace ringlet::behaviour::reactive {
namespace {

ReactiveParams five_arcs() {
  ReactiveParams p;
  p.arcs = {5, 2.0};  // κ = −2, −1, 0, 1, 2
  p.top_speed = 1.0;
  p.lookahead = 3.0;
  p.waypoint_gain = 2.0;
  p.vote_width = 1.0;
  p.stop_distance = 0.2;
  p.slow_distance = 1.5;
  p.congested_speed = 0.4;
  p.max_yaw_rate = 1.0;
  return p;
}

PerArc per_arc(std::initializer_list<double> v) {
  PerArc a{};
  std::copy(v.begin(), v.end(), a.begin());
  return a;
}

void expect_first(const PerArc& got, std::initializer_list<double> want) {
  std::size_t i = 0;
  for (double w : want) {
    EXPECT_NEAR(got[i], w, 1e-12) << "arc " << i;
    ++i;
  }
}

TEST(ReactiveArcs, AreEvenlySpacedOverTheSteeringRange) {
  const ArcSet a{5, 2.0};
  EXPECT_DOUBLE_EQ(a.curvature(0), -2.0);
  EXPECT_DOUBLE_EQ(a.curvature(1), -1.0);
  EXPECT_DOUBLE_EQ(a.curvature(2), 0.0);
  EXPECT_DOUBLE_EQ(a.curvature(4), 2.0);
  EXPECT_DOUBLE_EQ((ArcSet{1, 2.0}).curvature(0), 0.0);
  EXPECT_EQ(a.validate(), "");
  EXPECT_NE((ArcSet{0, 2.0}).validate().find("arcs must be 1 to 63"), std::string::npos);
  EXPECT_NE((ArcSet{5, -1.0}).validate().find("max_curvature"), std::string::npos);
}

TEST(ReactiveArcs, DistanceAlongAStraightArcToTheConfigurationSpace) {
  EXPECT_NEAR(distance_to_contact(0.0, {2.0, 0.3}, 0.5, 3.0), 1.6, 1e-12);  // 2 − √(0.25 − 0.09)
  EXPECT_EQ(distance_to_contact(0.0, {2.0, 0.6}, 0.5, 3.0), 3.0);            // passes beside it
  EXPECT_EQ(distance_to_contact(0.0, {-2.0, 0.0}, 0.5, 3.0), 3.0);           // behind
  EXPECT_EQ(distance_to_contact(0.0, {0.3, 0.0}, 0.5, 3.0), 0.0);            // already inside, and closer ahead
  EXPECT_EQ(distance_to_contact(0.0, {-0.3, 0.0}, 0.5, 3.0), 3.0);           // inside, but driving away
  EXPECT_EQ(distance_to_contact(0.0, {0.0, 0.4}, 0.5, 3.0), 3.0);            // a wall alongside: straight on is the way out
  EXPECT_EQ(distance_to_contact(1.0, {0.0, 0.4}, 0.5, 3.0), 3.0);            // turning right, away from it
  EXPECT_EQ(distance_to_contact(-1.0, {0.3, 0.3}, 0.5, 3.0), 0.0);           // ahead on the left: turning left into it is not
  EXPECT_EQ(distance_to_contact(0.0, {9.0, 0.0}, 0.5, 3.0), 3.0);            // beyond the limit
}

TEST(ReactiveArcs, DistanceAlongACurvedArcToTheConfigurationSpace) {
  // κ = 1 turns right around (0, −1); the point (1, −1) lies on the arc a quarter turn on. The
  // disc of radius 0.5 is met δ = acos((1 + 1 − 0.25) / 2) before it.
  const double want = std::numbers::pi / 2 - std::acos(0.875);
  EXPECT_NEAR(distance_to_contact(1.0, {1.0, -1.0}, 0.5, 3.0), want, 1e-12);
  EXPECT_NEAR(distance_to_contact(-1.0, {1.0, 1.0}, 0.5, 3.0), want, 1e-12);  // the mirror: a left turn
  EXPECT_EQ(distance_to_contact(1.0, {1.0, 1.0}, 0.5, 3.0), 3.0);             // on the other side
  // Three quarters of a turn on: (−1, −1), met at 3π/2 − δ, beyond a 3 m limit but not a 5 m one.
  EXPECT_EQ(distance_to_contact(1.0, {-1.0, -1.0}, 0.5, 3.0), 3.0);
  EXPECT_NEAR(distance_to_contact(1.0, {-1.0, -1.0}, 0.5, 5.0), 3 * std::numbers::pi / 2 - std::acos(0.875), 1e-12);
}

TEST(ReactiveArcs, ScanBeamsBecomeRobotFramePointsAndClearancesTakeTheNearest) {
  hal::LaserScan scan;
  scan.beam_count = 3;
  scan.angle_min = -std::numbers::pi / 2;
  scan.angle_increment = std::numbers::pi / 2;
  scan.range = {2.0f, 1.0f, 2.0f};
  scan.valid = {true, true, false};
  const ObstaclePoints o = obstacles_from_scan(scan);
  ASSERT_EQ(o.count, 2U);
  EXPECT_NEAR(o.point[0].x, 0.0, 1e-12);  // −90°: to the robot's left
  EXPECT_NEAR(o.point[0].y, 2.0, 1e-12);
  EXPECT_NEAR(o.point[1].x, 1.0, 1e-12);  // straight ahead
  EXPECT_NEAR(o.point[1].y, 0.0, 1e-12);
  PerArc c{};
  clearances({3, 2.0}, o, 0.5, 3.0, c);
  EXPECT_NEAR(c[1], 0.5, 1e-12);  // straight: 1 − 0.5
  EXPECT_NEAR(c[0], distance_to_contact(-2.0, o.point[0], 0.5, distance_to_contact(-2.0, o.point[1], 0.5, 3.0)), 1e-12);
}

/// A waypoint `distance` away at `error` rad clockwise of the heading, in the robot frame.
hal::RobotPoint at_error(double error, double distance) { return {distance * std::cos(error), -distance * std::sin(error)}; }

TEST(ReactiveBehaviours, MoveToWaypointVotesAroundTheLinearLawsArc) {
  const ReactiveParams p = five_arcs();
  ArcVotes v;
  EXPECT_NEAR(heading_error_to(at_error(0.25, 5.0)), 0.25, 1e-12);
  move_to_waypoint_votes(p, at_error(0.25, 5.0), v);  // κ* = 0.5: halfway between the straight arc and κ = 1
  expect_first(v.vote, {0.0, 0.0, 0.5, 0.5, 0.0});
  expect_first(v.max_speed, {1.0, 1.0, 1.0, 1.0, 1.0});
  move_to_waypoint_votes(p, at_error(-3.0, 5.0), v);  // κ* = −6, clamped to −2
  expect_first(v.vote, {1.0, 0.0, 0.0, 0.0, 0.0});
}

TEST(ReactiveBehaviours, MoveToWaypointDrivesOutOfATurningCircleItCannotReach) {
  const ReactiveParams p = five_arcs();  // tightest turn: radius 0.5 m
  ArcVotes v;
  // 0.3 m to the right, beside the robot: inside the right turning circle (centre (0, −0.5)).
  move_to_waypoint_votes(p, {0.0, -0.3}, v);
  expect_first(v.vote, {0.0, 0.0, 1.0, 0.0, 0.0});  // straight on, to get out
  // 1.2 m to the right: outside it, so turn right as hard as the law says (κ* = 2 · π/2, clamped).
  move_to_waypoint_votes(p, {0.0, -1.2}, v);
  expect_first(v.vote, {0.0, 0.0, 0.0, 0.0, 1.0});
}

TEST(ReactiveBehaviours, AvoidObstaclesVotesAgainstArcsThatMeetObstaclesSoon) {
  const ReactiveParams p = five_arcs();
  ArcVotes v;
  avoid_obstacles_votes(p, per_arc({3.0, 3.0, 1.5, 0.0, 3.0}), v);
  expect_first(v.vote, {0.0, 0.0, -0.5, -1.0, 0.0});
}

TEST(ReactiveBehaviours, MaintainHeadwayLimitsSpeedByTheClearance) {
  const ReactiveParams p = five_arcs();
  ArcVotes v;
  maintain_headway_votes(p, per_arc({3.0, 0.85, 0.2, 0.1, 1.5}), v);
  expect_first(v.vote, {0.0, 0.0, 0.0, 0.0, 0.0});
  expect_first(v.max_speed, {1.0, 0.5, 0.0, 0.0, 1.0});
}

TEST(ReactiveBehaviours, SlowForCongestedAreasInTheWideConfigurationSpace) {
  const ReactiveParams p = five_arcs();
  ArcVotes v;
  slow_for_congestion_votes(p, per_arc({3.0, 1.5, 0.0, 3.0, 3.0}), v);
  expect_first(v.max_speed, {1.0, 0.7, 0.4, 1.0, 1.0});  // 0.4 + 0.6 · 1.5 / 3
}

TEST(ReactiveBehaviours, SlowForTurnsKeepsTheYawRateBelowItsMaximum) {
  const ReactiveParams p = five_arcs();
  ArcVotes v;
  slow_for_turns_votes(p, v);
  expect_first(v.max_speed, {0.5, 1.0, 1.0, 1.0, 0.5});
}

TEST(ReactiveArbiter, WeightedSumPicksTheArcAndTheSlowestLimitOnIt) {
  const ReactiveParams p = five_arcs();  // weights: waypoint 1, avoid 2, the speed behaviours 0
  std::array<ArcVotes, kBehaviours> v{};
  move_to_waypoint_votes(p, at_error(0.25, 5.0), v[0]);
  avoid_obstacles_votes(p, per_arc({3.0, 3.0, 1.5, 0.0, 3.0}), v[1]);
  maintain_headway_votes(p, per_arc({3.0, 0.85, 0.2, 0.1, 1.5}), v[2]);
  slow_for_congestion_votes(p, per_arc({3.0, 1.5, 0.0, 3.0, 3.0}), v[3]);
  slow_for_turns_votes(p, v[4]);
  const ArbiterDecision d = arbitrate(p, v);
  // Totals: 1·(0, 0, .5, .5, 0) + 2·(0, 0, −.5, −1, 0) = (0, 0, −.5, −1.5, 0). Arcs 0, 1 and 4
  // tie at 0: the straightest, κ = −1, wins; its limits are 1, 1, 0.5, 0.7, 1.
  expect_first(d.total, {0.0, 0.0, -0.5, -1.5, 0.0});
  EXPECT_EQ(d.arc, 1);
  EXPECT_DOUBLE_EQ(d.curvature, -1.0);
  EXPECT_DOUBLE_EQ(d.speed, 0.5);
}

TEST(ReactiveArbiter, SymmetricTiesGoToTheLowerIndexAndWeightsMatter) {
  ReactiveParams p = five_arcs();
  std::array<ArcVotes, kBehaviours> v{};
  for (auto& b : v) {
    b.vote.fill(0.0);
    b.max_speed.fill(1.0);
  }
  v[0].vote = per_arc({0.0, 1.0, 0.0, 1.0, 0.0});
  EXPECT_EQ(arbitrate(p, v).arc, 1);  // κ = −1 and +1 tie: the lower index
  v[1].vote = per_arc({0.0, -0.2, 0.0, 0.0, 0.0});
  EXPECT_EQ(arbitrate(p, v).arc, 3);
  p.weight[1] = 0.0;  // avoid_obstacles silenced
  EXPECT_EQ(arbitrate(p, v).arc, 1);
}

TEST(ReactiveArbiter, AnArcNoBehaviourLetsTheRobotDriveIsChosenOnlyWhenAllAre) {
  const ReactiveParams p = five_arcs();
  std::array<ArcVotes, kBehaviours> v{};
  for (auto& b : v) {
    b.vote.fill(0.0);
    b.max_speed.fill(1.0);
  }
  v[0].vote = per_arc({0.0, 0.5, 1.0, 0.5, 0.0});
  v[2].max_speed = per_arc({1.0, 0.3, 0.0, 0.6, 1.0});  // headway: the straight arc ends at an obstacle
  ArbiterDecision d = arbitrate(p, v);
  EXPECT_EQ(d.arc, 1);  // the best arc that can be driven; κ = −1 and +1 tie: the lower index
  EXPECT_DOUBLE_EQ(d.speed, 0.3);
  v[2].max_speed.fill(0.0);  // boxed in
  d = arbitrate(p, v);
  EXPECT_EQ(d.arc, 2);
  EXPECT_EQ(d.speed, 0.0);
}

TEST(ReactiveStep, SteersAroundAnObstacleStraightAheadAndSlows) {
  ReactiveParams p;  // the defaults: 25 arcs over ±2 /m, 0.45 m configuration space
  ObstaclePoints o;
  for (int k = -3; k <= 3; ++k) o.point[o.count++] = {1.2, 0.05 * k};  // a post 1.2 m ahead
  ReactiveStep s;
  reactive_step(p, {5.0, 0.0}, o, s);
  const int straight = p.arcs.count / 2;
  EXPECT_NEAR(s.clearance[static_cast<std::size_t>(straight)], 1.2 - 0.45, 1e-12);
  EXPECT_NE(s.decision.arc, straight);
  EXPECT_GT(std::abs(s.decision.curvature), 0.0);
  EXPECT_GT(s.decision.speed, 0.0);
  EXPECT_LT(s.decision.speed, p.top_speed);
  // Nothing in the way: straight at the waypoint, full speed.
  ObstaclePoints none;
  reactive_step(p, {5.0, 0.0}, none, s);
  EXPECT_EQ(s.decision.arc, straight);
  EXPECT_DOUBLE_EQ(s.decision.speed, p.top_speed);
}

TEST(ReactiveParams, NameWhatIsWrong) {
  EXPECT_EQ(ReactiveParams{}.validate(), "");
  ReactiveParams p;
  p.slow_distance = 0.1;
  EXPECT_NE(p.validate().find("slow_distance"), std::string::npos);
  p = {};
  p.weight[2] = -1.0;
  EXPECT_NE(p.validate().find("weights.maintain_headway"), std::string::npos);
  p = {};
  p.congested_speed = 5.0;
  EXPECT_NE(p.validate().find("congested_speed"), std::string::npos);
}

}  // namespace
}  // namespace ringlet::behaviour::reactive
