// The ringlet contract (machine.hpp, behaviour/README.md) on hand-written machines.
#include <gtest/gtest.h>

#include <chrono>

#include "ringlet/hal/virtual_clock.hpp"
#include "scripted_machine.hpp"

namespace ringlet::behaviour::llfsm::test {
namespace {

using namespace std::chrono_literals;

Log take(Log& log) {
  Log out;
  out.swap(log);
  return out;
}

TEST(Ringlet, OnEntryOncePerEntryThenInternalWhileNothingFires) {
  Log log;
  ScriptedMachine m("M", {"A"}, log);
  m.ringlet(0ns);
  m.ringlet(1ns);
  m.ringlet(2ns);
  EXPECT_EQ(take(log), (Log{"M.snapshot:A", "M.entry:A", "M.internal:A", "M.write:A",  //
                            "M.snapshot:A", "M.internal:A", "M.write:A",               //
                            "M.snapshot:A", "M.internal:A", "M.write:A"}));
  EXPECT_EQ(m.ringlets(), 3u);
}

TEST(Ringlet, FirstTrueTransitionInDeclaredOrderFiresAndSkipsInternal) {
  Log log;
  ScriptedMachine m("M", {"A", "B", "C"}, log);
  m.add_transition(0, never, 2);
  m.add_transition(0, always, 1);  // first true one
  m.add_transition(0, always, 2);  // true too, but later
  m.ringlet(0ns);
  EXPECT_EQ(take(log), (Log{"M.snapshot:A", "M.entry:A", "M.exit:A", "M.write:A"}));
  EXPECT_EQ(m.current_state_name(), "B");
  m.ringlet(1ns);  // B entered since the last ringlet: OnEntry, nothing fires: Internal
  EXPECT_EQ(take(log), (Log{"M.snapshot:B", "M.entry:B", "M.internal:B", "M.write:B"}));
}

TEST(Ringlet, SelfTransitionRunsOnExitThenOnEntryAgainAndResetsStateTime) {
  Log log;
  ScriptedMachine m("M", {"A"}, log);
  m.add_transition(0, [](ScriptedMachine& s) { return s.after(10ns); }, 0);
  m.ringlet(0ns);
  m.ringlet(10ns);  // fires: OnExit
  m.ringlet(15ns);  // re-entered: OnEntry, state time 0 again
  m.ringlet(20ns);  // 5 ns in the state: nothing fires
  EXPECT_EQ(take(log), (Log{"M.snapshot:A", "M.entry:A", "M.internal:A", "M.write:A",  //
                            "M.snapshot:A", "M.exit:A", "M.write:A",                   //
                            "M.snapshot:A", "M.entry:A", "M.internal:A", "M.write:A",  //
                            "M.snapshot:A", "M.internal:A", "M.write:A"}));
  EXPECT_EQ(m.state_time(), 5ns);
}

TEST(Ringlet, StateChangesArePublished) {
  Log log;
  hal::VirtualClock clock;
  RecordingBus bus;
  Schedule sched(clock, &bus);
  ScriptedMachine m("M", {"A", "B"}, log);
  m.add_transition(0, always, 1);
  m.add_transition(1, always, 1);
  sched.add(m);
  sched.start();
  sched.run_turn(0ns);
  sched.run_turn(1ns);
  EXPECT_EQ(bus.events, (std::vector<std::string>{"M:->A[0]", "M:A->B[1]", "M:B->B[2]"}));
}

// --- suspend / resume / restart -----------------------------------------------------------------

TEST(Control, SuspendRunsOnSuspendAndStopsRingletsUntilResume) {
  Log log;
  ScriptedMachine m("M", {"A"}, log);
  m.ringlet(0ns);
  take(log);
  m.request(Request::kSuspend);
  m.ringlet(1ns);
  m.ringlet(2ns);
  EXPECT_TRUE(m.suspended());
  EXPECT_EQ(take(log), (Log{"M.snapshot:A", "M.suspend:A", "M.write:A"}));
  m.request(Request::kResume);
  m.ringlet(3ns);  // OnResume, then the ordinary ringlet in the same slot (no second OnEntry)
  EXPECT_EQ(take(log), (Log{"M.snapshot:A", "M.resume:A", "M.internal:A", "M.write:A"}));
  EXPECT_EQ(m.ringlets(), 2u);  // suspended slots are not ringlets
}

TEST(Control, RestartResetsLocalsAndReentersInitialWithoutOnExit) {
  Log log;
  ScriptedMachine m("M", {"A", "B"}, log);
  m.add_transition(0, always, 1);
  m.ringlet(0ns);
  m.ringlet(1ns);
  m.local = 42;
  take(log);
  m.request(Request::kRestart);
  m.ringlet(2ns);
  EXPECT_EQ(take(log), (Log{"M.reset", "M.snapshot:A", "M.entry:A", "M.exit:A", "M.write:A"}));
  EXPECT_EQ(m.local, 0);
}

TEST(Control, RestartOfSuspendedMachineAlsoResumesIt) {
  Log log;
  ScriptedMachine m("M", {"A"}, log);
  m.request(Request::kSuspend);
  m.ringlet(0ns);
  ASSERT_TRUE(m.suspended());
  m.request(Request::kRestart);
  m.ringlet(1ns);
  EXPECT_FALSE(m.suspended());
  EXPECT_EQ(m.ringlets(), 1u);
}

// Several requests before one ringlet: the highest priority wins, restart > suspend > resume,
// whatever the order they arrived in.
TEST(Control, SeveralRequestsInOneRingletResolveByPriority) {
  struct Case {
    std::vector<Request> requests;
    bool start_suspended;
    bool suspended_after;
    bool restarted;
  };
  const std::vector<Case> cases{
      {{Request::kSuspend, Request::kResume}, false, true, false},
      {{Request::kResume, Request::kSuspend}, false, true, false},
      {{Request::kResume, Request::kSuspend}, true, true, false},
      {{Request::kSuspend, Request::kRestart, Request::kResume}, false, false, true},
      {{Request::kRestart, Request::kSuspend}, true, false, true},
      {{Request::kResume, Request::kResume}, true, false, false},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(i);
    Log log;
    ScriptedMachine m("M", {"A"}, log);
    m.ringlet(0ns);
    if (cases[i].start_suspended) {
      m.request(Request::kSuspend);
      m.ringlet(1ns);
    }
    take(log);
    for (Request r : cases[i].requests) m.request(r);
    m.ringlet(2ns);
    EXPECT_EQ(m.suspended(), cases[i].suspended_after);
    EXPECT_EQ(!log.empty() && log.front() == "M.reset", cases[i].restarted);
    EXPECT_EQ(m.pending_request(), Request::kNone);
  }
}

TEST(Control, MachineRequestsTakeEffectAtTheTargetsNextRinglet) {
  Log log;
  hal::VirtualClock clock;
  Schedule sched(clock);
  ScriptedMachine early("Early", {"A"}, log);
  ScriptedMachine boss("Boss", {"Go", "Done"}, log);
  ScriptedMachine late("Late", {"A"}, log);
  boss.add_transition(0, [](ScriptedMachine& s) {
    EXPECT_TRUE(s.suspend_machine("Early"));
    EXPECT_TRUE(s.suspend_machine("Late"));
    EXPECT_FALSE(s.suspend_machine("Nobody"));
    return true;
  }, 1);
  sched.add(early);
  sched.add(boss);
  sched.add(late);
  sched.run_turn(0ns);
  // Late runs after Boss in the same turn: its ringlet starts with the suspend. Early already ran.
  EXPECT_TRUE(late.suspended());
  EXPECT_FALSE(early.suspended());
  sched.run_turn(1ns);
  EXPECT_TRUE(early.suspended());
  EXPECT_EQ(early.ringlets(), 1u);
  EXPECT_EQ(late.ringlets(), 0u);
}

TEST(Control, BusRequestsAreReadAtTheStartOfTheTurn) {
  Log log;
  hal::VirtualClock clock;
  RecordingBus bus;
  Schedule sched(clock, &bus);
  ScriptedMachine m("M", {"A"}, log);
  sched.add(m);
  sched.run_turn(0ns);
  bus.queued.emplace_back("M", Request::kSuspend);
  bus.queued.emplace_back("Unknown", Request::kSuspend);  // ignored
  sched.run_turn(1ns);
  EXPECT_TRUE(m.suspended());
  bus.queued.emplace_back("M", Request::kResume);
  sched.run_turn(2ns);
  EXPECT_FALSE(m.suspended());
  EXPECT_EQ(bus.events, (std::vector<std::string>{"M:->A[0]", "M:A->A[1] suspended", "M:A->A[1]"}));
}

// --- submachines ----------------------------------------------------------------------------------

TEST(Submachine, SuspendedUntilOwningStateEntersRestartedOnEntrySuspendedOnExit) {
  Log log;
  hal::VirtualClock clock;
  Schedule sched(clock);
  ScriptedMachine parent("P", {"Idle", "Active"}, log);
  ScriptedMachine child("C", {"One", "Two"}, log);
  bool active = false;
  parent.add_transition(0, [&](ScriptedMachine&) { return active; }, 1);
  parent.add_transition(1, [&](ScriptedMachine&) { return !active; }, 0);
  parent.own_submachine(1, "C", SubmachineEntry::kRestart);
  child.add_transition(0, always, 1);
  sched.add(parent);
  sched.add(child);
  sched.start();
  EXPECT_TRUE(child.suspended());
  sched.run_turn(0ns);
  EXPECT_EQ(child.ringlets(), 0u);
  active = true;
  sched.run_turn(1ns);  // P: Idle -> Active, C restarted in the same turn (it runs after P)
  EXPECT_FALSE(child.suspended());
  EXPECT_EQ(child.current_state_name(), "Two");
  active = false;
  take(log);
  sched.run_turn(2ns);  // P leaves Active: C's next ringlet is its suspension (OnSuspend)
  EXPECT_TRUE(child.suspended());
  EXPECT_EQ(take(log), (Log{"P.snapshot:Active", "P.entry:Active", "P.exit:Active", "P.write:Active",
                            "C.snapshot:Two", "C.suspend:Two", "C.write:Two"}));
  active = true;
  sched.run_turn(3ns);  // re-entered: restart mode starts C over from its initial state
  EXPECT_EQ(child.current_state_name(), "Two");
  EXPECT_EQ(log.back(), "C.write:One");
}

TEST(Submachine, ResumeModeContinuesWhereTheChildWasAndParentSuspensionPropagates) {
  Log log;
  hal::VirtualClock clock;
  Schedule sched(clock);
  ScriptedMachine parent("P", {"Active", "Idle"}, log);
  ScriptedMachine child("C", {"One", "Two", "Three"}, log);
  bool leave = false;
  parent.add_transition(0, [&](ScriptedMachine&) { return leave; }, 1);
  parent.add_transition(1, [&](ScriptedMachine&) { return !leave; }, 0);
  parent.own_submachine(0, "C", SubmachineEntry::kResume);
  child.add_transition(0, always, 1);
  child.add_transition(1, always, 2);
  sched.add(child);  // before the parent: every request reaches it one turn later
  sched.add(parent);
  sched.run_turn(0ns);  // C resumed from the initial hand-over
  EXPECT_EQ(child.current_state_name(), "Two");
  leave = true;
  sched.run_turn(1ns);  // C -> Three, then P leaves Active
  sched.run_turn(2ns);  // C suspended in Three
  EXPECT_TRUE(child.suspended());
  leave = false;
  sched.run_turn(3ns);  // P back in Active
  sched.run_turn(4ns);  // C resumed, still in Three
  EXPECT_FALSE(child.suspended());
  EXPECT_EQ(child.current_state_name(), "Three");
  // Suspending the parent suspends its current state's child; resuming resumes it.
  parent.request(Request::kSuspend);
  sched.run_turn(5ns);
  sched.run_turn(6ns);
  EXPECT_TRUE(parent.suspended());
  EXPECT_TRUE(child.suspended());
  parent.request(Request::kResume);
  sched.run_turn(7ns);
  sched.run_turn(8ns);
  EXPECT_FALSE(child.suspended());
}

TEST(Submachine, UnknownChildIsAStartUpError) {
  Log log;
  hal::VirtualClock clock;
  Schedule sched(clock);
  ScriptedMachine parent("P", {"A"}, log);
  parent.own_submachine(0, "Ghost", SubmachineEntry::kRestart);
  sched.add(parent);
  EXPECT_THROW(sched.start(), std::invalid_argument);
}

// --- schedule -------------------------------------------------------------------------------------

TEST(Schedule, RingletsPerTurnAndOrder) {
  Log log;
  hal::VirtualClock clock;
  Schedule sched(clock);
  ScriptedMachine a("A", {"S"}, log);
  ScriptedMachine b("B", {"S"}, log);
  sched.add(a, 2);
  sched.add(b, 1);
  EXPECT_THROW(sched.add(a), std::invalid_argument);
  ScriptedMachine zero("Z", {"S"}, log);
  EXPECT_THROW(sched.add(zero, 0), std::invalid_argument);
  sched.run_turn(0ns);
  sched.run_turn(1ns);
  EXPECT_EQ(a.ringlets(), 4u);
  EXPECT_EQ(b.ringlets(), 2u);
  EXPECT_EQ(log[4], "A.snapshot:S");  // A's two ringlets come before B's
  EXPECT_EQ(log[7], "B.snapshot:S");
  EXPECT_EQ(sched.turns(), 2u);
}

TEST(Schedule, StatsMeasureEachRingletWithTheStopwatch) {
  Log log;
  hal::VirtualClock clock;
  Schedule sched(clock, nullptr, Timing::kWallAndCpu);
  ScriptedMachine m("M", {"S"}, log);
  int cost = 0;
  m.on_internal(0, [&](ScriptedMachine&) { clock.advance(std::chrono::microseconds(++cost)); });
  sched.add(m, 3);
  sched.run_turn(0ns);
  const RingletStats* st = sched.stats("M");
  ASSERT_NE(st, nullptr);
  EXPECT_EQ(st->samples, 3u);
  EXPECT_EQ(st->max_wall, 3us);
  EXPECT_EQ(st->last_wall, 3us);
  EXPECT_EQ(st->total_wall, 6us);
  EXPECT_EQ(st->mean_wall(), 2us);
  EXPECT_EQ(st->max_cpu, 3us);
  EXPECT_EQ(sched.stats("nobody"), nullptr);

  Schedule wall_only(clock);  // the default: no CPU clock reads
  ScriptedMachine w("W", {"S"}, log);
  w.on_internal(0, [&](ScriptedMachine&) { clock.advance(5us); });
  wall_only.add(w);
  wall_only.run_turn(0ns);
  EXPECT_EQ(wall_only.stats(0).max_wall, 5us);
  EXPECT_EQ(wall_only.stats(0).max_cpu, 0ns);
}

// after() runs on the executive's `now`, so virtual time gives the same answer on every run.
TEST(Schedule, AfterIsLockstepOnVirtualTime) {
  const auto run = [] {
    Log log;
    hal::VirtualClock clock;
    Schedule sched(clock);
    ScriptedMachine m("M", {"Wait", "Go"}, log);
    m.add_transition(0, [](ScriptedMachine& s) { return s.after_ms(100); }, 1);
    sched.add(m);
    int fired_at = -1;
    for (int turn = 0; turn < 30 && fired_at < 0; ++turn) {
      sched.run_turn(std::chrono::milliseconds(5 + 10 * turn));  // OnEntry at 5 ms
      if (m.current_state_name() == "Go") fired_at = turn;
    }
    return fired_at;
  };
  EXPECT_EQ(run(), 10);  // 5 + 100 ms
  EXPECT_EQ(run(), run());
}

}  // namespace
}  // namespace ringlet::behaviour::llfsm::test
