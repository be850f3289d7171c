// Machines generated from tests/behaviour/models/*.machine at build time, on a real whiteboard.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>

#include "ringlet/behaviour/llfsm/providers.hpp"
#include "ringlet/behaviour/llfsm/schedule.hpp"
#include "ringlet/behaviour/llfsm/whiteboard_bus.hpp"
#include "ringlet/hal/virtual_clock.hpp"
#include "ringlet/test_machines/child.hpp"
#include "ringlet/test_machines/counter.hpp"
#include "ringlet/test_machines/echo.hpp"
#include "ringlet/test_machines/lexical.hpp"
#include "ringlet/test_machines/parent.hpp"
#include "ringlet/test_machines/timer.hpp"
#include "test_hooks.hpp"

namespace ringlet::behaviour::llfsm::test {
namespace {

using namespace std::chrono_literals;
using models::Child;
using models::Counter;
using models::Echo;
using models::Lexical;
using models::Parent;
using models::Timer;

// REQUIRES / PROVIDES are constexpr data, computed from the states' footprints.
static_assert(Echo::kRequires.size() == 1 && Echo::kRequires[0] == "Pose");
static_assert(Echo::kProvides.size() == 1 && Echo::kProvides[0] == "HeadCommand");
static_assert(Counter::kRequires.empty() && Counter::kProvides[0] == "Pose");
static_assert(Timer::kRequires.empty() && Timer::kProvides.empty());
static_assert(Echo::kStates[Echo::kStateIdle] == "Idle");
// Braces and quotes inside literals and comments of lexical.machine are text: both states remain.
static_assert(Lexical::kStates.size() == 2 && Lexical::kStates[Lexical::kStateDone] == "Done");

wb::Pose pose_x(double x) {
  wb::Pose p{};
  p.x = x;
  p.valid = true;
  return p;
}

struct GeneratedTest : ::testing::Test {
  wb::Whiteboard board{8};
  hal::VirtualClock clock;
  void TearDown() override { probe_hook() = nullptr; }
};

TEST_F(GeneratedTest, OnEntryOnceThenInternalCopiesTheSnapshot) {
  Schedule sched(clock);
  Echo echo(board);
  sched.add(echo);
  board.post(pose_x(3.0));
  sched.run_turn(0ns);
  sched.run_turn(1ns);
  EXPECT_EQ(echo.local_entries(), 1);
  EXPECT_EQ(board.get<wb::HeadCommand>().yaw, 3.0);
  EXPECT_EQ(board.generation<wb::HeadCommand>(), 2u);  // WRITE footprint posted every ringlet
}

TEST_F(GeneratedTest, AMachineKeepsItsSnapshotWhileOthersWrite) {
  Schedule sched(clock);
  Echo echo(board);
  sched.add(echo);
  board.post(pose_x(1.0));
  probe_hook() = [&] { board.post(pose_x(99.0)); };  // another writer, mid-ringlet
  sched.run_turn(0ns);
  EXPECT_EQ(echo.local_seen_after_probe(), 1.0);
  EXPECT_EQ(board.get<wb::HeadCommand>().yaw, 1.0);
  probe_hook() = nullptr;
  sched.run_turn(1ns);  // the next ringlet's snapshot sees it
  EXPECT_EQ(board.get<wb::HeadCommand>().yaw, 99.0);
}

TEST_F(GeneratedTest, WritesAreVisibleOnlyToLaterSnapshots) {
  // Echo before Counter sees last turn's count; an Echo after it sees this turn's.
  Schedule sched(clock);
  Echo before(board);
  Counter counter(board);
  sched.add(before);
  sched.add(counter);
  sched.run_turn(0ns);
  EXPECT_EQ(before.external_in().x, 0.0);
  sched.run_turn(1ns);
  EXPECT_EQ(before.external_in().x, 1.0);
  EXPECT_EQ(board.get<wb::Pose>().x, 2.0);
}

TEST_F(GeneratedTest, StatesOnlyTouchTheirOwnFootprint) {
  Schedule sched(clock);
  Echo echo(board);
  sched.add(echo);
  board.post(pose_x(-1.0));
  sched.run_turn(0ns);  // Copy: snapshot -1, post, -> Idle
  ASSERT_EQ(echo.current_state_name(), "Idle");
  const auto posts = board.generation<wb::HeadCommand>();
  board.post(pose_x(5.0));
  sched.run_turn(10ms);  // Idle mentions no external: no snapshot, no post
  EXPECT_EQ(echo.external_in().x, -1.0);
  EXPECT_EQ(board.generation<wb::HeadCommand>(), posts);
}

TEST_F(GeneratedTest, AfterRunsOnTheExecutiveClock) {
  Schedule sched(clock);
  Timer timer(board);
  sched.add(timer);
  std::vector<std::int64_t> changes;
  std::string_view last = timer.current_state_name();
  for (int ms = 0; ms <= 1000; ms += 10) {
    sched.run_turn(std::chrono::milliseconds(ms));
    if (timer.current_state_name() != last) {
      changes.push_back(ms);
      last = timer.current_state_name();
    }
  }
  // A entered at 0: -> B at 250; B entered at 260: -> A at 360; A entered at 370: -> B at 620...
  EXPECT_EQ(changes, (std::vector<std::int64_t>{250, 360, 620, 730, 990}));
}

TEST_F(GeneratedTest, StatusIsPostedAndFsmControlSuspendsByName) {
  WhiteboardFsmBus bus(board);
  Schedule sched(clock, &bus);
  Echo echo(board);
  sched.add(echo);
  sched.start();
  EXPECT_EQ(board.get<wb::FsmStatus>().state.view(), "Copy");
  board.post(pose_x(-1.0));
  sched.run_turn(0ns);
  wb::FsmStatus st = board.get<wb::FsmStatus>();
  EXPECT_EQ(st.machine.view(), "Echo");
  EXPECT_EQ(st.previous.view(), "Copy");
  EXPECT_EQ(st.state.view(), "Idle");
  EXPECT_EQ(st.ringlets, 1u);

  wb::FsmControl c{};
  c.machine = "Echo";
  c.command = wb::FsmCommand::kSuspend;
  board.post(c);
  c.machine = "Nobody";
  board.post(c);
  sched.run_turn(1ms);
  EXPECT_TRUE(echo.suspended());
  EXPECT_TRUE(board.get<wb::FsmStatus>().suspended);
  EXPECT_EQ(bus.unknown_machines(), 1u);
  // Several in one turn: restart beats suspend, whatever the order.
  c.machine = "Echo";
  c.command = wb::FsmCommand::kRestart;
  board.post(c);
  c.command = wb::FsmCommand::kSuspend;
  board.post(c);
  sched.run_turn(2ms);
  EXPECT_FALSE(echo.suspended());
  EXPECT_EQ(echo.local_entries(), 1);  // locals reset, then Copy's OnEntry once
}

TEST_F(GeneratedTest, FsmControlGenerationsLostToTheRingAreCounted) {
  wb::Whiteboard small(2);
  WhiteboardFsmBus bus(small);
  Schedule sched(clock, &bus);
  Echo echo(small);
  sched.add(echo);
  wb::FsmControl c{};
  c.machine = "Echo";
  c.command = wb::FsmCommand::kResume;
  for (int i = 0; i < 5; ++i) small.post(c);
  c.command = wb::FsmCommand::kSuspend;
  small.post(c);
  sched.run_turn(0ns);
  EXPECT_EQ(bus.missed_controls(), 4u);
  EXPECT_TRUE(echo.suspended());
}

TEST_F(GeneratedTest, SubmachineFollowsItsOwningState) {
  Schedule sched(clock);
  Parent parent(board);
  Child child(board);
  sched.add(parent);
  sched.add(child);
  sched.run_turn(0ns);
  EXPECT_TRUE(child.suspended());
  board.post(pose_x(0.0));  // valid: Parent -> Busy
  sched.run_turn(1ns);
  sched.run_turn(2ns);
  sched.run_turn(3ns);
  EXPECT_EQ(child.current_state_name(), "Three");
  wb::Pose off{};
  board.post(off);
  sched.run_turn(4ns);  // Parent leaves Busy: Child suspended in Three (OnSuspend)
  EXPECT_TRUE(child.suspended());
  EXPECT_EQ(child.local_suspensions(), 1);
  board.post(pose_x(0.0));
  sched.run_turn(5ns);  // re-entered: restart, locals reset
  EXPECT_FALSE(child.suspended());
  EXPECT_EQ(child.current_state_name(), "Two");
  EXPECT_EQ(child.local_suspensions(), 0);
}

TEST_F(GeneratedTest, ProviderCheckNamesMachineAndType) {
  Schedule sched(clock);
  Echo echo(board);
  sched.add(echo);
  ProviderReport r = check_providers(sched);
  ASSERT_EQ(r.missing.size(), 1u);
  EXPECT_EQ(r.missing[0].machine, "Echo");
  EXPECT_EQ(r.missing[0].type, "Pose");
  EXPECT_EQ(r.describe(), "machine 'Echo' requires 'Pose': no provider\n");
  const std::string_view tasks[] = {"Pose"};
  EXPECT_TRUE(check_providers(sched, tasks).ok());
  Schedule with_counter(clock);
  Echo echo2(board);
  Counter counter(board);
  with_counter.add(echo2);
  with_counter.add(counter);
  EXPECT_TRUE(check_providers(with_counter).ok());
}

// lexical.machine: the literals' braces counted at run time (the code block was not cut short),
// the guards with digit separators, a conditional and casts fire as written, in order.
TEST_F(GeneratedTest, LiteralsAndCommentsDoNotChangeTheStructure) {
  Schedule sched(clock);
  Lexical lexical(board);
  sched.add(lexical);
  board.post(pose_x(0.0));
  sched.run_turn(0ns);
  EXPECT_EQ(lexical.local_braces(), 2);
  EXPECT_EQ(board.get<wb::HeadCommand>().yaw, 2000.0);
  EXPECT_EQ(lexical.current_state(), Lexical::kStateScan);
  board.post(pose_x(1500.0));
  sched.run_turn(1ms);
  EXPECT_EQ(lexical.current_state(), Lexical::kStateDone);
  board.post(pose_x(-2000.0));
  sched.run_turn(1000ms);  // Done's first ringlet: its state time starts here
  sched.run_turn(2400ms);
  EXPECT_EQ(lexical.current_state(), Lexical::kStateDone);  // after(1'500ms) not yet
  sched.run_turn(2600ms);
  EXPECT_EQ(lexical.current_state(), Lexical::kStateScan);
}

}  // namespace
}  // namespace ringlet::behaviour::llfsm::test
