// Posting, reading, dispatching and the binary codec allocate nothing once subscriptions are made.
// The global operator new is replaced in this executable (only) to count allocations.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

#include "ringlet/whiteboard/whiteboard.hpp"

namespace {
std::atomic<std::size_t> g_allocations{0};

void* counted_alloc(std::size_t size, std::size_t align) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (size == 0) size = 1;
  void* p = align <= alignof(std::max_align_t)
                ? std::malloc(size)
                : std::aligned_alloc(align, (size + align - 1) / align * align);
  if (p == nullptr) throw std::bad_alloc{};
  return p;
}
}  // namespace

void* operator new(std::size_t size) { return counted_alloc(size, alignof(std::max_align_t)); }
void* operator new(std::size_t size, std::align_val_t align) {
  return counted_alloc(size, static_cast<std::size_t>(align));
}
// The array forms too: sanitizer runtimes intercept them directly instead of forwarding.
void* operator new[](std::size_t size) { return counted_alloc(size, alignof(std::max_align_t)); }
void* operator new[](std::size_t size, std::align_val_t align) {
  return counted_alloc(size, static_cast<std::size_t>(align));
}
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

namespace ringlet::wb {
namespace {

TEST(WbNoAllocation, PostGetReadDispatchAndBinary) {
  Whiteboard wb(8);
  double sum = 0.0;
  wb.subscribe<BallBelief>([&sum](const BallBelief& b) { sum += b.x; });
  wb.subscribe<Print>([&sum](const Print& p) { sum += static_cast<double>(p.text.size()); });
  std::array<std::byte, 256> buf{};
  Print print;
  print.text = "a message longer than any small-string buffer would hold, for sure";
  wb.dispatch();  // first dispatch: nothing pending

  const std::size_t before = g_allocations.load();
  for (int k = 0; k < 1000; ++k) {
    const double x = static_cast<double>(k);
    wb.post(BallBelief{true, x, -x, 0.5, false});
    wb.post(print);
    Handle<BallBelief>(wb).set(BallBelief{false, x, x, 0.25, true});
    sum += wb.get<BallBelief>().x;
    sum += wb.read<BallBelief>(wb.generation<BallBelief>()).msg.y;
    sum += wb.has_new<Print>(0) ? 1.0 : 0.0;
    sum += static_cast<double>(wb.get<Print>().text.size());
    wb.dispatch();
    const std::size_t n = encode(wb.get<BallBelief>(), buf);
    const Result<BallBelief> back = decode<BallBelief>(std::span(buf).first(n));
    sum += back->x;
    const Result<HeadCommand> parsed = HeadCommand::from_string("0.25,-1e-3");
    sum += parsed->yaw;
  }
  const std::size_t after = g_allocations.load();
  EXPECT_EQ(after - before, 0U);
  EXPECT_GT(sum, 0.0);
}

TEST(WbNoAllocation, CounterWorks) {
  const std::size_t before = g_allocations.load();
  Whiteboard wb;  // the rings are allocated here
  EXPECT_GT(g_allocations.load(), before);
}

}  // namespace
}  // namespace ringlet::wb
