// The shipped machines (behaviour/machines/*.machine) in a lockstep schedule.
#include <gtest/gtest.h>

#include <chrono>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <array>

#include "ringlet/behaviour/llfsm/providers.hpp"
#include "ringlet/behaviour/llfsm/schedule.hpp"
#include "ringlet/behaviour/machines/ball_tracker.hpp"
#include "ringlet/behaviour/machines/mission.hpp"
#include "ringlet/behaviour/machines/safety.hpp"
#include "ringlet/hal/virtual_clock.hpp"

namespace ringlet::behaviour::machines {
namespace {

using namespace std::chrono_literals;

static_assert(BallTracker::kRequires.size() == 1 && BallTracker::kRequires[0] == "BallBelief");
static_assert(BallTracker::kProvides.size() == 1 && BallTracker::kProvides[0] == "HeadCommand");
static_assert(Safety::kRequires[0] == "LaserSummary" && Safety::kProvides[0] == "MotionCommand");
static_assert(Mission::kRequires.size() == 2 && Mission::kRequires[0] == "Pose" &&
              Mission::kRequires[1] == "MissionGoals");
static_assert(Mission::kProvides.size() == 2 && Mission::kProvides[0] == "MotionCommand" &&
              Mission::kProvides[1] == "MissionStatus");

wb::LaserSummary laser(double nearest) {
  wb::LaserSummary l{};
  l.nearest_range = nearest;
  l.valid_beams = 100;
  return l;
}

struct MachinesTest : ::testing::Test {
  wb::Whiteboard board{8};
  hal::VirtualClock clock;
  llfsm::Schedule sched{clock};
  BallTracker tracker{board};
  // A square of 2 m sides from the origin, back home.
  Mission mission{board, MoveToWaypointParams{}};

  // A square of 2 m sides from the origin, back home.
  void post_square() {
    wb::MissionGoals goals{};
    goals.count = 4;
    goals.x = {2.0, 2.0, 0.0, 0.0};
    goals.y = {0.0, 2.0, 2.0, 0.0};
    goals.tolerance = 0.3;
    board.post(goals);
  }
  Safety safety{board, 0.5, 0.8, 300};  // stop, release (m), hold (ms)
};

TEST_F(MachinesTest, BallTrackerPointsTheHeadAtTheBall) {
  sched.add(tracker);
  sched.run_turn(0ns);  // Init -> Loop
  EXPECT_EQ(tracker.current_state_name(), "Loop");
  wb::BallBelief ball{};
  ball.visible = true;
  ball.x = 1.0;
  ball.y = 1.0;
  board.post(ball);
  sched.run_turn(1ms);  // Loop -> UpdateHead
  sched.run_turn(2ms);  // UpdateHead: aim
  const wb::HeadCommand head = board.get<wb::HeadCommand>();
  EXPECT_NEAR(head.yaw, std::numbers::pi / 4.0, 1e-12);
  EXPECT_NEAR(head.pitch, std::atan2(0.5, std::sqrt(2.0)), 1e-12);  // down onto the ball
  ball.y = -0.1;  // behind, to the right: beyond the neck, clamped
  ball.x = -1.0;
  board.post(ball);
  sched.run_turn(3ms);
  sched.run_turn(4ms);
  EXPECT_DOUBLE_EQ(board.get<wb::HeadCommand>().yaw, -2.0);
}

// Loop sees the ball in one ringlet and UpdateHead aims in the next, from a newer snapshot: when
// vision has posted "gone" in between (x = y = 0), the head stays where it aimed last, instead of
// turning to the front and pitching down at its own feet.
TEST_F(MachinesTest, BallTrackerKeepsItsAimWhenTheBallIsGoneByTheTimeItAims) {
  sched.add(tracker);
  sched.run_turn(0ns);  // Init -> Loop
  wb::BallBelief ball{};
  ball.visible = true;
  ball.x = 0.5;
  ball.y = 1.5;
  board.post(ball);
  sched.run_turn(1ms);  // Loop -> UpdateHead
  sched.run_turn(2ms);  // UpdateHead aims
  const wb::HeadCommand aimed = board.get<wb::HeadCommand>();
  ASSERT_NEAR(aimed.yaw, std::atan2(1.5, 0.5), 1e-12);
  sched.run_turn(3ms);  // Loop sees the ball again -> UpdateHead
  ASSERT_EQ(tracker.current_state_name(), "UpdateHead");
  board.post(wb::BallBelief{});  // gone before UpdateHead's ringlet reads its snapshot
  sched.run_turn(4ms);
  EXPECT_EQ(board.get<wb::HeadCommand>().yaw, aimed.yaw);
  EXPECT_EQ(board.get<wb::HeadCommand>().pitch, aimed.pitch);
}

// A ball lost from view (e.g. behind a robot's legs) is searched for from where the head last
// aimed at it: the sweep starts there and rises, instead of swinging back to the front first.
TEST_F(MachinesTest, BallTrackerSearchesFromWhereItLastSawTheBall) {
  sched.add(tracker);
  hal::Nanos t{0};
  const auto turn = [&] {
    sched.run_turn(t);
    t += 10ms;
  };
  turn();  // Init -> Loop
  wb::BallBelief ball{};
  ball.visible = true;
  ball.x = 0.2;  // far to the left: yaw 1.37 rad
  ball.y = 1.0;
  board.post(ball);
  turn();
  turn();
  const double aimed = std::atan2(1.0, 0.2);
  ASSERT_NEAR(board.get<wb::HeadCommand>().yaw, aimed, 1e-12);
  ball.visible = false;
  board.post(ball);
  for (int i = 0; i < 40; ++i) turn();  // lost for 400 ms: the head holds still meanwhile
  EXPECT_EQ(tracker.current_state_name(), "Loop");
  EXPECT_NEAR(board.get<wb::HeadCommand>().yaw, aimed, 1e-12);
  for (int i = 0; i < 20 && tracker.current_state_name() != "Search"; ++i) turn();  // lost_ms 500
  ASSERT_EQ(tracker.current_state_name(), "Search");
  turn();  // the sweep's first command (the swing of the old sweep began at the front, yaw 0)
  const double first = board.get<wb::HeadCommand>().yaw;
  EXPECT_NEAR(first, aimed, 0.02) << "the sweep starts where the ball was";
  turn();
  const double rising = board.get<wb::HeadCommand>().yaw;
  EXPECT_GT(rising, first) << "and first goes on the same way";
  double lowest = rising;
  for (int i = 0; i < 400; ++i) {  // 4 s: more than a whole sweep (2π / 1.2 rad/s = 5.2 s) half over
    turn();
    lowest = std::min(lowest, board.get<wb::HeadCommand>().yaw);
  }
  EXPECT_LT(lowest, -1.4) << "then sweeps the other side too";
  EXPECT_NEAR(board.get<wb::HeadCommand>().pitch, 0.35, 1e-12);
}

TEST_F(MachinesTest, SafetyStopsWithHysteresisAndHoldsTheMission) {
  sched.add(mission);
  sched.add(safety, 2);
  const std::string_view tasks[] = {"Pose", "LaserSummary", "BallBelief", "MissionGoals"};
  EXPECT_TRUE(llfsm::check_providers(sched, tasks).ok());
  post_square();
  wb::Pose pose{};
  pose.valid = true;
  board.post(pose);
  board.post(laser(2.0));
  hal::Nanos t{0};
  const auto turn = [&] {
    sched.run_turn(t);
    t += 10ms;
  };
  turn();  // Safety starts Stopped (fail-safe) and suspends Mission
  turn();
  EXPECT_TRUE(board.get<wb::MotionCommand>().stop);
  EXPECT_TRUE(mission.suspended());
  for (int i = 0; i < 35; ++i) turn();  // clear for > 300 ms: released, Mission resumed
  EXPECT_EQ(safety.current_state_name(), "Clear");
  turn();
  EXPECT_FALSE(mission.suspended());
  EXPECT_FALSE(board.get<wb::MotionCommand>().stop);
  EXPECT_GT(board.get<wb::MotionCommand>().velocity, 0.0);

  board.post(laser(0.6));  // inside release_range but not stop_range: keeps going
  turn();
  EXPECT_EQ(safety.current_state_name(), "Clear");
  board.post(laser(0.4));  // too close: the stop stands at the end of this very turn
  turn();
  EXPECT_TRUE(board.get<wb::MotionCommand>().stop);
  turn();  // and from the next turn on the Mission is suspended
  EXPECT_TRUE(mission.suspended());
  EXPECT_TRUE(board.get<wb::MotionCommand>().stop);
  board.post(laser(0.7));  // between the thresholds: stays stopped
  for (int i = 0; i < 50; ++i) turn();
  EXPECT_EQ(safety.current_state_name(), "Stopped");
  EXPECT_EQ(safety.local_stops(), 2u);
}

TEST_F(MachinesTest, MissionAdvancesThroughItsGoals) {
  sched.add(mission);
  post_square();
  sched.run_turn(0ns);
  EXPECT_EQ(mission.current_state_name(), "WaitForPose");
  wb::Pose pose{};
  pose.valid = true;
  board.post(pose);
  sched.run_turn(1ms);  // -> Drive
  sched.run_turn(2ms);
  EXPECT_GT(board.get<wb::MotionCommand>().velocity, 0.0);
  for (const auto& [x, y] : {std::pair{2.0, 0.0}, {2.0, 2.0}, {0.0, 2.0}, {0.0, 0.0}}) {
    pose.x = x;
    pose.y = y;
    board.post(pose);
    for (int i = 0; i < 3; ++i) sched.run_turn(3ms);  // Drive (sees it), -> Reached, -> Drive/Done
  }
  sched.run_turn(4ms);  // Done's OnEntry: the stop
  EXPECT_EQ(mission.current_state_name(), "Done");
  EXPECT_EQ(mission.local_announced(), 4u);
  const wb::MissionStatus status = board.get<wb::MissionStatus>();
  EXPECT_TRUE(status.done);
  EXPECT_TRUE(board.get<wb::MotionCommand>().stop);
}

}  // namespace
}  // namespace ringlet::behaviour::machines
