// EventLog: FIFO order, dropping when full, and the single-producer / single-consumer contract
// across two threads.
#include <gtest/gtest.h>

#include <cstdint>
#include <thread>

#include "ringlet/executive/event_log.hpp"

namespace ringlet::executive {
namespace {

Event numbered(std::uint64_t n) {
  Event e;
  e.kind = static_cast<EventKind>(n % 3);
  e.task = static_cast<std::uint16_t>(n % 7);
  e.frame = n;
  e.measured = Nanos{static_cast<std::int64_t>(n) * 3};
  e.suppressed = n ^ 0x5555U;
  return e;
}

TEST(EventLog, EmptyPopFails) {
  EventLog log;
  Event e;
  EXPECT_FALSE(log.pop(e));
  EXPECT_EQ(log.dropped(), 0U);
}

TEST(EventLog, FifoOrderPreservesEveryField) {
  EventLog log;
  for (std::uint64_t i = 0; i < 10; ++i) ASSERT_TRUE(log.push(numbered(i)));
  for (std::uint64_t i = 0; i < 10; ++i) {
    Event e;
    ASSERT_TRUE(log.pop(e));
    const Event want = numbered(i);
    EXPECT_EQ(e.frame, want.frame);
    EXPECT_EQ(e.kind, want.kind);
    EXPECT_EQ(e.task, want.task);
    EXPECT_EQ(e.measured, want.measured);
    EXPECT_EQ(e.suppressed, want.suppressed);
  }
  Event e;
  EXPECT_FALSE(log.pop(e));
}

TEST(EventLog, FullRingDropsAndCounts) {
  EventLog log;
  for (std::uint64_t i = 0; i < EventLog::kCapacity; ++i) ASSERT_TRUE(log.push(numbered(i))) << i;
  for (std::uint64_t i = 0; i < 5; ++i) EXPECT_FALSE(log.push(numbered(1000 + i)));
  EXPECT_EQ(log.dropped(), 5U);

  Event e;
  ASSERT_TRUE(log.pop(e));
  EXPECT_EQ(e.frame, 0U);
  EXPECT_TRUE(log.push(numbered(2000)));  // room for exactly one again
  EXPECT_FALSE(log.push(numbered(2001)));
  EXPECT_EQ(log.dropped(), 6U);

  for (std::uint64_t i = 1; i < EventLog::kCapacity; ++i) {
    ASSERT_TRUE(log.pop(e));
    EXPECT_EQ(e.frame, i);  // the dropped events never appear
  }
  ASSERT_TRUE(log.pop(e));
  EXPECT_EQ(e.frame, 2000U);
  EXPECT_FALSE(log.pop(e));
}

TEST(EventLog, WrapsAroundManyTimes) {
  EventLog log;
  std::uint64_t next_out = 0;
  for (std::uint64_t i = 0; i < 10 * EventLog::kCapacity; ++i) {
    ASSERT_TRUE(log.push(numbered(i)));
    if (i % 3 != 0) {  // consume a little slower than we produce, never overflowing
      Event e;
      ASSERT_TRUE(log.pop(e));
      ASSERT_EQ(e.frame, next_out++);
    }
    if (i % 128 == 127) {
      Event e;
      while (log.pop(e)) ASSERT_EQ(e.frame, next_out++);
    }
  }
  EXPECT_EQ(log.dropped(), 0U);
}

TEST(EventLog, SpscAcrossTwoThreadsKeepsOrder) {
  constexpr std::uint64_t kEvents = 100'000;
  EventLog log;
  std::uint64_t failed_pushes = 0;
  std::thread producer([&] {
    for (std::uint64_t i = 0; i < kEvents; ++i) {
      const Event e = numbered(i);
      while (!log.push(e)) {
        ++failed_pushes;
        std::this_thread::yield();
      }
    }
  });

  std::uint64_t expected = 0;
  std::uint64_t out_of_order = 0;
  std::uint64_t bad_payload = 0;
  Event e;
  while (expected < kEvents) {
    if (!log.pop(e)) {
      std::this_thread::yield();
      continue;
    }
    if (e.frame != expected) ++out_of_order;
    const Event want = numbered(e.frame);
    if (e.measured != want.measured || e.suppressed != want.suppressed || e.task != want.task) ++bad_payload;
    expected = e.frame + 1;
  }
  producer.join();
  EXPECT_EQ(out_of_order, 0U);
  EXPECT_EQ(bad_payload, 0U);
  EXPECT_FALSE(log.pop(e));
  EXPECT_EQ(log.dropped(), failed_pushes);  // every failed attempt is counted as a drop
}

}  // namespace
}  // namespace ringlet::executive
