// run_turn never allocates: allocations are counted (tests/support/allocation_counter) while
// a schedule of the shipped machines runs through state changes, suspensions and FsmControl requests.
#include <gtest/gtest.h>

#include <array>
#include <chrono>

#include "allocation_counter.hpp"
#include "ringlet/behaviour/llfsm/schedule.hpp"
#include "ringlet/behaviour/llfsm/whiteboard_bus.hpp"
#include "ringlet/behaviour/machines/ball_tracker.hpp"
#include "ringlet/behaviour/machines/mission.hpp"
#include "ringlet/behaviour/machines/safety.hpp"
#include "ringlet/hal/virtual_clock.hpp"


namespace ringlet::behaviour::machines {
namespace {

using namespace std::chrono_literals;

TEST(LlfsmAllocation, TurnsDoNotAllocate) {
  wb::Whiteboard board(8);
  hal::VirtualClock clock;
  llfsm::WhiteboardFsmBus bus(board);
  llfsm::Schedule sched(clock, &bus);
  BallTracker tracker(board);
  wb::MissionGoals goals{};
  goals.count = 2;
  goals.x[0] = 5.0;
  goals.tolerance = 0.3;
  board.post(goals);
  Mission mission(board, MoveToWaypointParams{});
  Safety safety(board, 0.5, 0.8, 300);
  sched.add(tracker);
  sched.add(mission);
  sched.add(safety, 2);
  sched.start();

  const std::uint64_t before = ringlet::test::allocations();
  wb::Pose pose{};
  pose.valid = true;
  wb::LaserSummary laser{};
  laser.valid_beams = 10;
  wb::BallBelief ball{};
  wb::FsmControl control{};
  control.machine = "BallTracker";
  for (int turn = 0; turn < 2000; ++turn) {
    laser.nearest_range = (turn / 100) % 2 == 0 ? 2.0 : 0.3;  // stop, release, stop, ...
    ball.visible = turn % 3 != 0;
    ball.x = 1.0 + turn % 7;
    pose.x = (turn % 500) * 0.01;
    board.post(laser);
    board.post(ball);
    board.post(pose);
    if (turn % 50 == 0) {
      control.command = turn % 150 == 0 ? wb::FsmCommand::kRestart
                        : turn % 100 == 0 ? wb::FsmCommand::kSuspend : wb::FsmCommand::kResume;
      board.post(control);
    }
    sched.run_turn(std::chrono::milliseconds(10 * turn));
  }
  EXPECT_EQ(ringlet::test::allocations() - before, 0U);
  EXPECT_GT(tracker.ringlets(), 100u);
  EXPECT_GT(safety.local_stops(), 2u);
}

}  // namespace
}  // namespace ringlet::behaviour::machines
