// One writer, three readers on other threads, a small ring so that the writer laps readers all the
// time: every message a reader is handed must be one whole generation (all fields derived from
// one counter), generations must never go backwards, and delivered + missed must add up exactly.
// Run under ThreadSanitizer by `tools/ringlet test` (stage tsan).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::wb {
namespace {

constexpr std::uint64_t kPosts = 60000;

ExecutiveTiming timing(std::uint64_t k) {
  ExecutiveTiming t;
  t.frames = k;
  t.frame_overruns = k * 3;
  t.slips = ~k;
  t.task_count = static_cast<std::uint16_t>(k & 0xFFFF);
  for (std::size_t i = 0; i < t.task_worst_ns.size(); ++i) {
    t.task_worst_ns[i] = static_cast<std::int64_t>(k * 7 + i);
  }
  return t;
}

bool consistent(const ExecutiveTiming& t) { return t == timing(t.frames); }

TEST(WbConcurrency, OneWriterThreeReadersNeverSeeATornMessage) {
  Whiteboard wb(4);
  std::atomic<bool> done{false};
  std::atomic<std::uint64_t> torn{0};
  std::atomic<std::uint64_t> backwards{0};
  std::atomic<std::uint64_t> wrong_generation{0};
  std::atomic<std::uint64_t> ok_reads{0};
  std::atomic<std::uint64_t> missed_reads{0};

  // Reader 2 is the "executive": it dispatches a kCycle subscription while the writer runs.
  std::uint64_t delivered = 0;
  std::uint64_t last_delivered = 0;
  const SubscriptionId sub = wb.subscribe<ExecutiveTiming>(
      std::function<void(const ExecutiveTiming&, const DeliveryInfo&)>(
          [&](const ExecutiveTiming& t, const DeliveryInfo& d) {
            if (!consistent(t)) torn.fetch_add(1);
            if (t.frames != d.generation) wrong_generation.fetch_add(1);
            if (d.generation != last_delivered + d.missed + 1) wrong_generation.fetch_add(1);
            last_delivered = d.generation;
            ++delivered;
          }));

  auto newest_reader = [&] {
    std::uint64_t last = 0;
    while (!done.load(std::memory_order_acquire)) {
      const ExecutiveTiming t = wb.get<ExecutiveTiming>();
      if (t == ExecutiveTiming{}) continue;  // nothing posted yet
      if (!consistent(t)) torn.fetch_add(1);
      if (t.frames < last) backwards.fetch_add(1);
      last = t.frames;
    }
  };
  auto generation_reader = [&] {
    std::uint64_t next = 1;
    while (!done.load(std::memory_order_acquire) || next <= wb.generation<ExecutiveTiming>()) {
      const ReadResult<ExecutiveTiming> r = wb.read<ExecutiveTiming>(next);
      switch (r.status) {
        case ReadStatus::kOk:
          if (!consistent(r.msg)) torn.fetch_add(1);
          if (r.msg.frames != next) wrong_generation.fetch_add(1);
          ok_reads.fetch_add(1);
          ++next;
          break;
        case ReadStatus::kMissed:
          if (r.missed == 0) wrong_generation.fetch_add(1);
          missed_reads.fetch_add(r.missed);
          next += r.missed;
          break;
        case ReadStatus::kNotYet: std::this_thread::yield(); break;
      }
    }
  };
  auto dispatcher = [&] {
    while (!done.load(std::memory_order_acquire)) wb.dispatch();
    wb.dispatch();
  };

  std::vector<std::thread> readers;
  readers.emplace_back(newest_reader);
  readers.emplace_back(generation_reader);
  readers.emplace_back(dispatcher);
  std::thread writer([&] {
    for (std::uint64_t k = 1; k <= kPosts; ++k) wb.post(timing(k));
    done.store(true, std::memory_order_release);
  });
  writer.join();
  for (auto& t : readers) t.join();

  EXPECT_EQ(torn.load(), 0U);
  EXPECT_EQ(backwards.load(), 0U);
  EXPECT_EQ(wrong_generation.load(), 0U);
  EXPECT_EQ(ok_reads.load() + missed_reads.load(), kPosts);  // every generation accounted for
  EXPECT_EQ(delivered + wb.missed(sub), kPosts);
  EXPECT_EQ(last_delivered, kPosts);
  EXPECT_EQ(wb.get<ExecutiveTiming>(), timing(kPosts));
}

TEST(WbConcurrency, ToolThreadReadsWhileTheWriterPosts) {
  Whiteboard wb(2);
  std::atomic<std::uint64_t> torn{0};
  std::atomic<std::uint64_t> delivered{0};
  const SubscriptionId sub = wb.subscribe<ExecutiveTiming>(
      [&](const ExecutiveTiming& t) {
        if (!consistent(t)) torn.fetch_add(1);
        delivered.fetch_add(1);
      },
      Delivery::kToolThread);
  wb.start_tool_thread(std::chrono::milliseconds{0});
  for (std::uint64_t k = 1; k <= kPosts / 4; ++k) wb.post(timing(k));
  wb.stop_tool_thread();
  EXPECT_EQ(torn.load(), 0U);
  EXPECT_EQ(delivered.load() + wb.missed(sub), kPosts / 4);
}

}  // namespace
}  // namespace ringlet::wb
