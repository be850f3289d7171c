// Generations: newest, counting, has_new, reading by generation and exact overrun reporting.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::wb {
namespace {

Pose pose(std::uint64_t k) { return Pose{static_cast<double>(k), 0.0, 0.0, true}; }

TEST(WbGenerations, NothingPostedReadsAsDefault) {
  Whiteboard wb;
  EXPECT_EQ(wb.generation<Pose>(), 0U);
  EXPECT_FALSE(wb.has_new<Pose>(0));
  EXPECT_EQ(wb.get<Pose>(), Pose{});
  EXPECT_EQ(wb.read<Pose>(1).status, ReadStatus::kNotYet);
  EXPECT_EQ(wb.read<Pose>(0).status, ReadStatus::kNotYet);
}

TEST(WbGenerations, CountNewestAndHasNew) {
  Whiteboard wb;
  wb.post(pose(1));
  wb.post(pose(2));
  EXPECT_EQ(wb.generation<Pose>(), 2U);
  EXPECT_EQ(wb.get<Pose>(), pose(2));
  EXPECT_TRUE(wb.has_new<Pose>(1));
  EXPECT_FALSE(wb.has_new<Pose>(2));
  EXPECT_EQ(wb.generation<HeadCommand>(), 0U);  // types are independent
}

TEST(WbGenerations, ReadByGenerationWithinTheRing) {
  Whiteboard wb(8);
  for (std::uint64_t k = 1; k <= 8; ++k) wb.post(pose(k));
  for (std::uint64_t g = 1; g <= 8; ++g) {
    const auto r = wb.read<Pose>(g);
    ASSERT_EQ(r.status, ReadStatus::kOk) << g;
    EXPECT_EQ(r.generation, g);
    EXPECT_EQ(r.msg, pose(g));
  }
  EXPECT_EQ(wb.read<Pose>(9).status, ReadStatus::kNotYet);
}

TEST(WbGenerations, OverrunReportsExactlyHowManyWereMissed) {
  Whiteboard wb(4);
  for (std::uint64_t k = 1; k <= 11; ++k) wb.post(pose(k));  // ring holds 8..11
  for (std::uint64_t g = 1; g <= 7; ++g) {
    const auto r = wb.read<Pose>(g);
    ASSERT_EQ(r.status, ReadStatus::kMissed) << g;
    EXPECT_EQ(r.missed, 8 - g) << g;
    EXPECT_EQ(wb.read<Pose>(g + r.missed).status, ReadStatus::kOk);
  }
  EXPECT_EQ(wb.read<Pose>(8).msg, pose(8));
}

// A polling reader gets every generation the ring still holds, oldest first, and one count of
// those it lost; a second call with nothing new posted reads nothing.
TEST(WbGenerations, ReadSinceDeliversEveryHeldGenerationAndCountsTheLost) {
  Whiteboard wb(4);
  std::uint64_t seen = 0;
  std::vector<double> got;
  std::uint64_t lost = 0;
  const auto take = [&got](const Pose& p) { got.push_back(p.x); };
  const auto count = [&lost](std::uint64_t n) { lost += n; };
  wb.post(pose(1));
  wb.post(pose(2));
  wb.read_since<Pose>(seen, take, count);
  EXPECT_EQ(got, (std::vector<double>{1.0, 2.0}));
  EXPECT_EQ(seen, 2U);
  for (std::uint64_t k = 3; k <= 11; ++k) wb.post(pose(k));  // ring holds 8..11: 3..7 are lost
  wb.read_since<Pose>(seen, take, count);
  EXPECT_EQ(got, (std::vector<double>{1.0, 2.0, 8.0, 9.0, 10.0, 11.0}));
  EXPECT_EQ(lost, 5U);
  EXPECT_EQ(seen, 11U);
  wb.read_since<Pose>(seen, take, count);
  EXPECT_EQ(got.size(), 6U);
  EXPECT_EQ(lost, 5U);
}

TEST(WbGenerations, DepthIsRoundedUpToAPowerOfTwo) {
  EXPECT_EQ(Whiteboard(0).depth(), 2U);
  EXPECT_EQ(Whiteboard(5).depth(), 8U);
  EXPECT_EQ(Whiteboard(16).depth(), 16U);
  EXPECT_EQ(Whiteboard{}.depth(), 8U);
}

TEST(WbGenerations, LargeMessagesKeepEveryByte) {
  Whiteboard wb(2);
  Print p;
  p.text = std::string(128, 'x');
  wb.post(p);
  EXPECT_EQ(wb.get<Print>().text.view(), std::string(128, 'x'));
}

TEST(WbHandle, IsTheTypedTView) {
  Whiteboard wb;
  Print_t print(wb);
  Print p;
  p.text = "We are about to loop for ever";
  print.set(p);
  EXPECT_EQ(print.get().text, "We are about to loop for ever");
  EXPECT_EQ(print.generation(), 1U);
  EXPECT_TRUE(print.has_new(0));
  EXPECT_TRUE(print.read(1).ok());
  Handle<BallBelief> ball(wb);
  EXPECT_EQ(ball.get(), BallBelief{});
}

}  // namespace
}  // namespace ringlet::wb
