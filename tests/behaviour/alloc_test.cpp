// run_turn never allocates: the global operator new is replaced to count, and a schedule of the
// shipped machines runs through state changes, suspensions and FsmControl requests.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <new>

#include "ringlet/behaviour/llfsm/schedule.hpp"
#include "ringlet/behaviour/llfsm/whiteboard_bus.hpp"
#include "ringlet/behaviour/machines/ball_tracker.hpp"
#include "ringlet/behaviour/machines/mission.hpp"
#include "ringlet/behaviour/machines/safety.hpp"
#include "ringlet/hal/virtual_clock.hpp"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace ringlet::behaviour::machines {
namespace {

using namespace std::chrono_literals;

TEST(LlfsmAllocation, TurnsDoNotAllocate) {
  wb::Whiteboard board(8);
  hal::VirtualClock clock;
  llfsm::WhiteboardFsmBus bus(board);
  llfsm::Schedule sched(clock, &bus);
  BallTracker tracker(board);
  const std::array<Waypoint, 2> goals_xy{{{5.0, 0.0}, {0.0, 0.0}}};
  WaypointMission goals(goals_xy, 0.3, MoveToWaypointParams{});
  Mission mission(board, goals);
  Safety safety(board, 0.5, 0.8, 300);
  sched.add(tracker);
  sched.add(mission);
  sched.add(safety, 2);
  sched.start();

  const long before = g_allocations.load();
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
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_GT(tracker.ringlets(), 100u);
  EXPECT_GT(safety.local_stops(), 2u);
}

}  // namespace
}  // namespace ringlet::behaviour::machines
