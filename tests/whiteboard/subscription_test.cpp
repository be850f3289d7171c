// Subscriptions: deterministic dispatch order, every generation delivered, misses reported,
// start-up-only subscribing, and the tool thread.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::wb {
namespace {

using namespace std::chrono_literals;

TEST(WbDispatch, OrderIsTypeIdThenSubscriptionOrder) {
  Whiteboard wb;
  std::vector<std::string> log;
  // Subscribed in a scrambled type order on purpose.
  wb.subscribe<Print>([&](const Print& p) { log.push_back("Print#1 " + std::string(p.text.view())); });
  wb.subscribe<HeadCommand>([&](const HeadCommand& h) { log.push_back("Head#1 " + std::to_string(h.yaw)); });
  wb.subscribe<Print>([&](const Print& p) { log.push_back("Print#2 " + std::string(p.text.view())); });
  wb.subscribe<BallBelief>([&](const BallBelief&) { log.push_back("Ball#1"); });

  Print p;
  p.text = "a";
  wb.post(p);
  wb.post(HeadCommand{1.0, 0.0});
  p.text = "b";
  wb.post(p);
  wb.post(BallBelief{});
  EXPECT_TRUE(log.empty());  // nothing runs until dispatch
  wb.dispatch();
  EXPECT_EQ(log, (std::vector<std::string>{"Ball#1", "Head#1 1.000000", "Print#1 a", "Print#1 b",
                                           "Print#2 a", "Print#2 b"}));
  log.clear();
  wb.dispatch();
  EXPECT_TRUE(log.empty());  // nothing new
}

TEST(WbDispatch, StartsAfterTheGenerationCurrentAtSubscription) {
  Whiteboard wb;
  wb.post(Pose{1.0, 0.0, 0.0, true});
  std::vector<double> xs;
  wb.subscribe<Pose>([&](const Pose& p) { xs.push_back(p.x); });
  wb.post(Pose{2.0, 0.0, 0.0, true});
  wb.dispatch();
  EXPECT_EQ(xs, (std::vector<double>{2.0}));
}

TEST(WbDispatch, EveryGenerationOrTheMissedCount) {
  Whiteboard wb(4);
  std::vector<std::uint64_t> gens;
  std::vector<std::uint64_t> missed;
  const SubscriptionId id = wb.subscribe<Pose>(
      std::function<void(const Pose&, const DeliveryInfo&)>([&](const Pose& p, const DeliveryInfo& d) {
        EXPECT_EQ(p.x, static_cast<double>(d.generation));
        gens.push_back(d.generation);
        missed.push_back(d.missed);
      }));
  for (int k = 1; k <= 3; ++k) wb.post(Pose{static_cast<double>(k), 0.0, 0.0, true});
  wb.dispatch();
  EXPECT_EQ(gens, (std::vector<std::uint64_t>{1, 2, 3}));
  EXPECT_EQ(wb.missed(id), 0U);

  gens.clear();
  missed.clear();
  for (int k = 4; k <= 13; ++k) wb.post(Pose{static_cast<double>(k), 0.0, 0.0, true});  // 10 > 4
  wb.dispatch();
  EXPECT_EQ(gens, (std::vector<std::uint64_t>{10, 11, 12, 13}));
  EXPECT_EQ(missed, (std::vector<std::uint64_t>{6, 0, 0, 0}));  // 4..9 were overwritten
  EXPECT_EQ(wb.missed(id), 6U);
}

TEST(WbDispatch, SubscribingAfterStartIsRefused) {
  Whiteboard wb;
  wb.subscribe<Pose>([](const Pose&) {});
  wb.dispatch();
  EXPECT_THROW(wb.subscribe<Pose>([](const Pose&) {}), std::logic_error);
}

TEST(WbToolThread, DeliversOffTheWritersThread) {
  Whiteboard wb;
  std::atomic<int> seen{0};
  std::atomic<bool> other_thread{false};
  const auto writer = std::this_thread::get_id();
  wb.subscribe<MotionCommand>(
      [&](const MotionCommand& m) {
        other_thread = std::this_thread::get_id() != writer;
        EXPECT_EQ(m.velocity, static_cast<double>(seen.load() + 1));
        seen.fetch_add(1);
      },
      Delivery::kToolThread);
  int cycle_calls = 0;
  wb.subscribe<MotionCommand>([&](const MotionCommand&) { ++cycle_calls; });
  wb.start_tool_thread(1ms);
  EXPECT_TRUE(wb.tool_thread_running());
  for (int k = 1; k <= 5; ++k) wb.post(MotionCommand{0.0, static_cast<double>(k), false});
  const auto deadline = std::chrono::steady_clock::now() + 5s;
  while (seen.load() < 5 && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(1ms);
  wb.stop_tool_thread();
  EXPECT_FALSE(wb.tool_thread_running());
  EXPECT_EQ(seen.load(), 5);
  EXPECT_TRUE(other_thread.load());
  EXPECT_EQ(cycle_calls, 0);  // kCycle ones wait for dispatch()
  wb.dispatch();
  EXPECT_EQ(cycle_calls, 5);
}

TEST(WbToolThread, StopDeliversWhatWasPostedBefore) {
  Whiteboard wb;
  std::atomic<int> seen{0};
  wb.subscribe<Print>([&](const Print&) { seen.fetch_add(1); }, Delivery::kToolThread);
  wb.start_tool_thread(std::chrono::milliseconds{10000});  // its first pass may come before the post
  wb.post(Print{});
  wb.stop_tool_thread();
  EXPECT_EQ(seen.load(), 1);
}

}  // namespace
}  // namespace ringlet::wb
