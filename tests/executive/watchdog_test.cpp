// The watchdog: its decision logic on virtual time, and the polling thread on the real clock
// (bounded waits only; the single timing bound is a generous 2 s).
#include <gtest/gtest.h>
#include <pthread.h>
#include <sched.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <string>
#include <thread>

#include "executive_test_support.hpp"
#include "ringlet/executive/executive.hpp"
#include "ringlet/executive/realtime.hpp"
#include "ringlet/executive/watchdog.hpp"
#include "ringlet/hal/monotonic_clock.hpp"

namespace ringlet::executive::test {
namespace {

// Polls `done` every millisecond for at most 2 s of real time.
template <typename Pred>
bool eventually(Pred done) {
  const auto give_up = std::chrono::steady_clock::now() + 2s;
  while (!done()) {
    if (std::chrono::steady_clock::now() > give_up) return false;
    std::this_thread::sleep_for(1ms);
  }
  return true;
}

TEST(WatchdogMonitor, NoTripWhileTheHeartbeatMoves) {
  WatchdogMonitor m(50ms);
  std::uint64_t beat = 0;
  for (int i = 0; i < 1000; ++i) {
    // A beat every 40 ms: slow but within the timeout.
    ASSERT_FALSE(m.observe(beat, Nanos{i} * 40'000'000)) << "observation " << i;
    ++beat;
  }
  EXPECT_FALSE(m.tripped());
  EXPECT_EQ(m.stalled_for(), Nanos{0});
}

TEST(WatchdogMonitor, TripsExactlyOnceAfterTheTimeout) {
  const Nanos t0 = kStart;
  WatchdogMonitor m(50ms);
  EXPECT_FALSE(m.observe(7, t0));  // first sight: starts the clock
  EXPECT_FALSE(m.observe(7, t0 + 20ms));
  EXPECT_EQ(m.stalled_for(), 20ms);
  EXPECT_FALSE(m.observe(7, t0 + 50ms));  // at the timeout: not yet "longer than"
  EXPECT_FALSE(m.tripped());
  EXPECT_TRUE(m.observe(7, t0 + 50ms + Nanos{1}));
  EXPECT_TRUE(m.tripped());
  EXPECT_EQ(m.stalled_for(), 50ms + Nanos{1});
  EXPECT_FALSE(m.observe(7, t0 + 80ms));  // once only
  EXPECT_EQ(m.stalled_for(), 80ms);
  EXPECT_TRUE(m.tripped());
  // Even a later, new stall does not trip it again: the safe state is latched anyway.
  EXPECT_FALSE(m.observe(8, t0 + 90ms));
  EXPECT_EQ(m.stalled_for(), Nanos{0});
  EXPECT_FALSE(m.observe(8, t0 + 500ms));
  EXPECT_TRUE(m.tripped());
}

TEST(WatchdogMonitor, StallIsMeasuredFromTheLastChange) {
  WatchdogMonitor m(50ms);
  Nanos t = kStart;
  for (std::uint64_t beat = 0; beat < 4; ++beat, t += 10ms) EXPECT_FALSE(m.observe(beat, t));
  const Nanos last_change = t - 10ms;  // beat 3
  EXPECT_FALSE(m.observe(3, last_change + 50ms));
  EXPECT_TRUE(m.observe(3, last_change + 51ms));
  EXPECT_EQ(m.stalled_for(), 51ms);
}

TEST(WatchdogMonitor, OnVirtualTimeFollowsTheExecutiveHeartbeat) {
  Rig rig;
  rig.add(spec("t", 1, 0, 2ms), 1ms);
  auto& exec = rig.build();
  WatchdogMonitor m(5 * 10ms);
  for (int i = 0; i < 20; ++i) {
    exec.run(1);
    EXPECT_FALSE(m.observe(exec.heartbeat().load(), rig.clock.now()));
  }
  // The cycle stops; time goes on.
  bool tripped = false;
  for (int i = 0; i < 10 && !tripped; ++i) {
    rig.clock.advance(10ms);
    tripped = m.observe(exec.heartbeat().load(), rig.clock.now());
  }
  EXPECT_TRUE(tripped);
  EXPECT_GT(m.stalled_for(), 50ms);
  EXPECT_LE(m.stalled_for(), 60ms);
}

TEST(WatchdogThread, StalledHeartbeatEntersTheSafeState) {
  hal::MonotonicClock clock;
  FakeActuators actuators;
  std::atomic<std::uint64_t> heartbeat{42};
  WatchdogThread dog(clock, heartbeat, actuators, 20ms, 2ms);
  EXPECT_TRUE(eventually([&] { return dog.fired(); })) << "watchdog did not fire within 2 s";
  EXPECT_TRUE(actuators.in_safe_state());
  EXPECT_EQ(actuators.safe_calls(), 1);
  EXPECT_GT(dog.stalled_for(), 20ms);
  EXPECT_FALSE(dog.shutdown_seen());
  dog.stop();
  dog.stop();  // idempotent
}

TEST(WatchdogThread, ShutdownFlagEntersTheSafeState) {
  hal::MonotonicClock clock;
  FakeActuators actuators;
  std::atomic<std::uint64_t> heartbeat{0};
  std::atomic<bool> shutdown{false};
  WatchdogThread dog(clock, heartbeat, actuators, 10s, 2ms, &shutdown);
  std::this_thread::sleep_for(10ms);
  EXPECT_FALSE(actuators.in_safe_state());
  EXPECT_FALSE(dog.shutdown_seen());
  shutdown.store(true);
  EXPECT_TRUE(eventually([&] { return dog.shutdown_seen(); })) << "shutdown not seen within 2 s";
  EXPECT_TRUE(actuators.in_safe_state());
  EXPECT_FALSE(dog.fired());  // a shutdown is not a stall
  dog.stop();
  EXPECT_EQ(actuators.safe_calls(), 1);  // commanded once, not on every poll
}

TEST(WatchdogThread, MovingHeartbeatNeverFires) {
  hal::MonotonicClock clock;
  FakeActuators actuators;
  std::atomic<std::uint64_t> heartbeat{0};
  // A bump every millisecond against a 1 s timeout: a loaded machine or qemu can delay a sleep
  // by tens of milliseconds, never by a second.
  WatchdogThread dog(clock, heartbeat, actuators, 1s, 2ms);
  const auto end = std::chrono::steady_clock::now() + 300ms;
  while (std::chrono::steady_clock::now() < end) {
    heartbeat.fetch_add(1);
    std::this_thread::sleep_for(1ms);
  }
  dog.stop();  // before the bumps end, so a slow machine cannot turn the test into a stall
  EXPECT_FALSE(dog.fired());
  EXPECT_FALSE(actuators.in_safe_state());
  EXPECT_GT(heartbeat.load(), 10U);
}

TEST(WatchdogThread, HungTaskInTheExecutiveTripsIt) {
  // The executive on virtual time, its heartbeat watched on the real clock; the task in frame 3
  // hangs until the safe state is commanded (bounded to 2 s).
  Rig rig;
  auto& t = rig.add(spec("hangs", 1, 0, 2ms), 1ms);
  auto& actuators = rig.actuators;
  t.on_run([&actuators](const TaskContext& ctx) {
    if (ctx.frame != 3) return;
    const auto give_up = std::chrono::steady_clock::now() + 2s;
    while (!actuators.in_safe_state() && std::chrono::steady_clock::now() < give_up) std::this_thread::sleep_for(1ms);
  });
  auto& exec = rig.build();
  hal::MonotonicClock clock;
  WatchdogThread dog(clock, exec.heartbeat(), rig.actuators, 20ms, 2ms, &exec.stop_flag());
  exec.run(5);
  dog.stop();
  EXPECT_TRUE(dog.fired());
  EXPECT_TRUE(rig.actuators.in_safe_state());
  EXPECT_EQ(exec.frame_stats().frames, 5U);
}

TEST(WatchdogPriority, OneAboveTheCycle) {
  const int top = sched_get_priority_max(SCHED_FIFO);
  EXPECT_EQ(watchdog_priority(0), 0);  // no real-time cycle: the watchdog keeps the normal scheduler
  EXPECT_EQ(watchdog_priority(50), 51);
  EXPECT_EQ(watchdog_priority(top - 1), top);
  EXPECT_EQ(watchdog_priority(top), top);  // nothing above the top: the same priority
}

// A thread's scheduler as the kernel reports it; policy -1 if it could not be read.
struct Scheduler {
  int policy = -1;
  int priority = -1;
};
Scheduler scheduler_of(pthread_t thread) {
  Scheduler s;
  sched_param param{};
  if (pthread_getschedparam(thread, &s.policy, &param) != 0) return Scheduler{};
  s.priority = param.sched_priority;
  return s;
}

// A watchdog that never fires during a test (10 s timeout, the heartbeat never read as stalled
// that long), for what concerns its thread rather than its decisions.
struct IdleWatchdog {
  hal::MonotonicClock clock;
  FakeActuators actuators;
  std::atomic<std::uint64_t> heartbeat{0};
  WatchdogThread dog{clock, heartbeat, actuators, 10s, 2ms};
};

TEST(WatchdogThread, TakesTheSchedFifoPriorityItIsGivenOrSaysWhyNot) {
  // Granted where the process may (root, CAP_SYS_NICE, an RLIMIT_RTPRIO), refused elsewhere: both
  // are legitimate here, so each outcome is checked for what it must then be.
  IdleWatchdog w;
  const auto warnings = set_fifo_priority(w.dog.native_handle(), 3, "watchdog");
  const Scheduler now = scheduler_of(w.dog.native_handle());
  ASSERT_NE(now.policy, -1);
  if (warnings.empty()) {
    EXPECT_EQ(now.policy, SCHED_FIFO);
    EXPECT_EQ(now.priority, 3);
  } else {
    ASSERT_EQ(warnings.size(), 1U);
    EXPECT_NE(warnings[0].find("SCHED_FIFO priority not granted to the watchdog"), std::string::npos) << warnings[0];
    EXPECT_NE(now.policy, SCHED_FIFO);
  }
  // The kernel shows it by name, so a check on the robot can find it.
  char name[16] = {};
  EXPECT_TRUE(eventually([&] {
    return pthread_getname_np(w.dog.native_handle(), name, sizeof name) == 0 && std::strcmp(name, "rl-watchdog") == 0;
  })) << "thread name: " << name;
  w.dog.stop();
  EXPECT_FALSE(w.dog.fired());
}

TEST(WatchdogThread, AnOutOfRangePriorityIsAWarningAndChangesNothing) {
  IdleWatchdog w;
  const Scheduler before = scheduler_of(w.dog.native_handle());
  ASSERT_NE(before.policy, -1);
  const int too_high = sched_get_priority_max(SCHED_FIFO) + 1;
  const auto warnings = set_fifo_priority(w.dog.native_handle(), too_high, "watchdog");
  ASSERT_EQ(warnings.size(), 1U);
  EXPECT_NE(warnings[0].find("realtime priority " + std::to_string(too_high) + " for the watchdog is outside"),
            std::string::npos)
      << warnings[0];
  const Scheduler after = scheduler_of(w.dog.native_handle());
  ASSERT_NE(after.policy, -1);
  EXPECT_EQ(after.policy, before.policy);
  EXPECT_EQ(after.priority, before.priority);
  w.dog.stop();
}

}  // namespace
}  // namespace ringlet::executive::test
