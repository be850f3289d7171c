// Posting, reading, dispatching and the binary codec allocate nothing once subscriptions are made.
// Allocations are counted by tests/support/allocation_counter (a replaced global operator new).
#include <gtest/gtest.h>

#include <array>
#include <cstddef>

#include "allocation_counter.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"


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

  const std::uint64_t before = ringlet::test::allocations();
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
  const std::uint64_t after = ringlet::test::allocations();
  EXPECT_EQ(after - before, 0U);
  EXPECT_GT(sum, 0.0);
}

TEST(WbNoAllocation, CounterWorks) {
  const std::uint64_t before = ringlet::test::allocations();
  Whiteboard wb;  // the rings are allocated here
  EXPECT_GT(ringlet::test::allocations(), before);
}

}  // namespace
}  // namespace ringlet::wb
