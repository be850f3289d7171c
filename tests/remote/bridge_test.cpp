// The bridge end to end over Cyclone DDS on loopback: a monitor-side reader (another participant,
// as ringlet-monitor has) receives every FsmStatus the whiteboard saw, in order; a monitor that
// joins late still gets every machine's current state; two robots are told apart; what the ring
// overwrote before the bridge read it, and what a rate limit leaves out, is counted.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "remote_test_support.hpp"
#include "ringlet/remote/bridge.hpp"

namespace ringlet::remote {
namespace {

using namespace std::chrono_literals;

using test::eventually;
using test::test_domain;

// Takes what the reader holds, appending to `out`.
template <wb::Message T>
void take(dds_entity_t reader, std::vector<typename DdsType<T>::Sample>& out) {
  constexpr int kBatch = 32;
  std::vector<typename DdsType<T>::Sample> buf(kBatch);
  void* ptrs[kBatch];
  dds_sample_info_t infos[kBatch];
  for (int i = 0; i < kBatch; ++i) ptrs[i] = &buf[static_cast<std::size_t>(i)];
  for (;;) {
    const dds_return_t n = dds_take(reader, ptrs, infos, kBatch, kBatch);
    ASSERT_GE(n, 0) << dds_strretcode(n);
    for (int i = 0; i < n; ++i) {
      if (infos[i].valid_data) out.push_back(buf[static_cast<std::size_t>(i)]);
    }
    if (n < kBatch) return;
  }
}

template <wb::Message T>
std::vector<typename DdsType<T>::Sample> receive(dds_entity_t reader, std::size_t want) {
  std::vector<typename DdsType<T>::Sample> got;
  eventually([&] {
    take<T>(reader, got);
    return got.size() >= want;
  });
  return got;
}

wb::FsmStatus status(const char* machine, std::uint64_t ringlets) {
  wb::FsmStatus s;
  s.machine = machine;
  s.state = ringlets % 2 == 0 ? "Even" : "Odd";
  s.ringlets = ringlets;
  return s;
}

BridgeConfig robot_config(std::uint16_t robot, const DomainConfig& domain) {
  BridgeConfig config;
  config.robot = robot;
  config.domain = domain;
  return config;
}

// Every generation 1..posts exactly once, from `robot`, and each machine's ringlets rising (DDS
// keeps the order per instance: per robot and machine).
void expect_every_status_once_in_order(const std::vector<DdsType<wb::FsmStatus>::Sample>& got, std::uint64_t posts,
                                       std::uint16_t robot) {
  ASSERT_EQ(got.size(), posts);
  std::vector<bool> seen(posts + 1, false);
  std::map<std::string, std::uint64_t> last;
  for (const auto& s : got) {
    EXPECT_EQ(s.robot, robot);
    ASSERT_TRUE(s.generation >= 1 && s.generation <= posts) << s.generation;
    EXPECT_FALSE(seen[s.generation]) << "generation " << s.generation << " twice";
    seen[s.generation] = true;
    EXPECT_GT(s.ringlets, last[s.machine]) << s.machine << " out of order";
    last[s.machine] = s.ringlets;
  }
}

TEST(RemoteBridge, AMonitorReceivesEveryFsmStatusInOrder) {
  const DomainConfig domain = test_domain();
  wb::Whiteboard board;
  Bridge bridge(board, robot_config(7, domain));
  Participant monitor(domain);
  const dds_entity_t reader = monitor.reader<wb::FsmStatus>(true);
  ASSERT_TRUE(eventually([&] { return bridge.matched_readers<wb::FsmStatus>() == 1; }));

  // Three machines, 300 statuses, posted faster than the ring (8 generations) would keep if the
  // bridge did not read after each: the bridge pumps after every post here, as a lockstep run's
  // pacing lets it.
  const char* machines[] = {"Safety", "Mission", "BallTracker"};
  constexpr std::uint64_t kPosts = 300;
  for (std::uint64_t i = 1; i <= kPosts; ++i) {
    board.post(status(machines[i % 3], i));
    bridge.pump();
  }
  ASSERT_TRUE(bridge.flush(10s));
  const auto got = receive<wb::FsmStatus>(reader, kPosts);
  expect_every_status_once_in_order(got, kPosts, 7);
  for (const auto& st : got) EXPECT_EQ(st.ringlets, st.generation);  // posted with ringlets = its generation
  const TypeCounts c = bridge.counts(wb::FsmStatus::kId);
  EXPECT_EQ(c.sent, kPosts);
  EXPECT_EQ(c.missed, 0U);
  EXPECT_EQ(c.failed, 0U);
}

TEST(RemoteBridge, AMonitorInAnotherProcessReceivesEveryFsmStatusOverUdp) {
  // Two processes on loopback: the robot's (child) and the monitor's (this one). Forked before
  // either touches DDS, so each has its own Cyclone DDS instance and the samples cross UDP.
  const DomainConfig domain = test_domain();
  constexpr std::uint64_t kPosts = 300;
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    int rc = 1;
    try {
      wb::Whiteboard board;
      Bridge bridge(board, robot_config(9, domain));
      if (eventually([&] { return bridge.matched_readers<wb::FsmStatus>() == 1; }, 20s)) {
        for (std::uint64_t i = 1; i <= kPosts; ++i) {
          board.post(status(i % 2 == 0 ? "Safety" : "Mission", i));
          bridge.pump();
        }
        const bool acked = bridge.flush(20s);
        rc = acked && bridge.counts(wb::FsmStatus::kId).sent == kPosts ? 0 : 2;
      }
    } catch (...) {
      rc = 3;
    }
    ::_exit(rc);
  }
  std::vector<DdsType<wb::FsmStatus>::Sample> got;
  {
    Participant monitor(domain);
    const dds_entity_t reader = monitor.reader<wb::FsmStatus>(true);
    got = receive<wb::FsmStatus>(reader, kPosts);
  }
  int wstatus = 0;
  ASSERT_EQ(::waitpid(child, &wstatus, 0), child);
  ASSERT_TRUE(WIFEXITED(wstatus));
  EXPECT_EQ(WEXITSTATUS(wstatus), 0) << "the robot process: 1 no monitor matched, 2 not all acknowledged, 3 threw";
  expect_every_status_once_in_order(got, kPosts, 9);
}

TEST(RemoteBridge, ALateMonitorSeesEveryMachinesCurrentState) {
  const DomainConfig domain = test_domain();
  wb::Whiteboard board;
  Bridge bridge(board, robot_config(3, domain));
  bridge.start();
  for (std::uint64_t i = 1; i <= 30; ++i) {
    board.post(status(i % 2 == 0 ? "Safety" : "Mission", i));
    std::this_thread::sleep_for(1ms);
  }
  ASSERT_TRUE(eventually([&] { return bridge.counts(wb::FsmStatus::kId).sent + bridge.counts(wb::FsmStatus::kId).missed == 30; }));

  Participant monitor(domain);  // joins after everything was published
  const dds_entity_t reader = monitor.reader<wb::FsmStatus>();
  std::map<std::string, std::uint64_t> newest;
  eventually([&] {
    std::vector<DdsType<wb::FsmStatus>::Sample> got;
    take<wb::FsmStatus>(reader, got);
    for (const auto& s : got) newest[s.machine] = std::max(newest[s.machine], s.ringlets);
    return newest["Safety"] == 30 && newest["Mission"] == 29;
  });
  EXPECT_EQ(newest["Safety"], 30U);
  EXPECT_EQ(newest["Mission"], 29U);
  bridge.stop();
}

TEST(RemoteBridge, TwoRobotsAreToldApart) {
  const DomainConfig domain = test_domain();
  wb::Whiteboard board1, board2;
  Bridge robot1(board1, robot_config(1, domain));
  Bridge robot2(board2, robot_config(2, domain));
  Participant monitor(domain);
  const dds_entity_t reader = monitor.reader<wb::Pose>();
  ASSERT_TRUE(eventually([&] {
    return robot1.matched_readers<wb::Pose>() == 1 && robot2.matched_readers<wb::Pose>() == 1;
  }));
  // Telemetry is best effort: post until the monitor has heard from both robots.
  std::map<int, double> x_of;
  eventually([&] {
    wb::Pose p1, p2;
    p1.x = 1.5;
    p2.x = -2.5;
    board1.post(p1);
    board2.post(p2);
    robot1.pump();
    robot2.pump();
    std::vector<DdsType<wb::Pose>::Sample> got;
    take<wb::Pose>(reader, got);
    for (const auto& s : got) x_of[s.robot] = s.x;
    return x_of.size() == 2;
  });
  ASSERT_EQ(x_of.size(), 2U);
  EXPECT_EQ(x_of[1], 1.5);
  EXPECT_EQ(x_of[2], -2.5);
}

TEST(RemoteBridge, WhatTheRingOverwroteAndWhatTheRateLimitLeftOutAreCounted) {
  const DomainConfig domain = test_domain();
  wb::Whiteboard board(8);
  BridgeConfig config;
  config.domain = domain;
  config.types[wb::kIndexOf<wb::BallBelief>].min_period = std::chrono::hours(1);
  config.types[wb::kIndexOf<wb::LaserSummary>].publish = false;
  Bridge bridge(board, config);
  for (int i = 0; i < 20; ++i) {
    board.post(wb::Pose{});
    board.post(wb::BallBelief{});
    board.post(wb::LaserSummary{});
  }
  bridge.pump();
  const TypeCounts pose = bridge.counts(wb::Pose::kId);
  EXPECT_EQ(pose.sent, 8U);     // the ring holds 8
  EXPECT_EQ(pose.missed, 12U);  // the 12 before them were overwritten
  const TypeCounts ball = bridge.counts(wb::BallBelief::kId);
  EXPECT_EQ(ball.sent, 1U);  // the newest
  EXPECT_EQ(ball.rate_skipped, 19U);
  for (int i = 0; i < 5; ++i) board.post(wb::BallBelief{});
  bridge.pump();  // within the period: nothing more
  EXPECT_EQ(bridge.counts(wb::BallBelief::kId).sent, 1U);
  EXPECT_EQ(bridge.counts(wb::LaserSummary::kId).sent, 0U);  // not published at all
  EXPECT_EQ(bridge.matched_readers<wb::LaserSummary>(), 0U);
}

TEST(RemoteBridge, AnotherConfigurationOfABusyDomainIsRefusedByName) {
  const DomainConfig domain = test_domain();
  Participant first(domain);
  DomainConfig other = domain;
  other.cyclone_config = "<CycloneDDS><Domain Id=\"any\"/></CycloneDDS>";
  try {
    Participant second(other);
    FAIL() << "a second configuration of domain 0 was accepted";
  } catch (const RemoteError& e) {
    EXPECT_NE(std::string(e.what()).find("DDS domain 0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ringlet::remote
