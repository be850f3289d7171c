// The centre circle's score (circle_score.hpp): recall counted by the circle's distance, where the
// far circles, a pixel or two of paint high, are lost.
#include <gtest/gtest.h>

#include <vector>

#include "circle_score.hpp"

namespace ringlet::vision::evaluate {
namespace {

TruthRing ring_at(double x, double y, double visible_fraction = 1.0) {
  TruthRing r;
  r.centre = {x, y};
  r.visible = true;
  r.visible_fraction = visible_fraction;
  return r;
}

TEST(CircleScore, RecallIsCountedByTheCirclesDistance) {
  CircleCounts total;
  // Found 2 m away, missed 3.5 m away, found 4.2 m away (diagonally), missed 7 m away, and one
  // 3.5 m away seen over 36° only: not expected, in no bin.
  total += score_circle({true, {2.05, 0.0}, 0.75}, std::vector<TruthRing>{ring_at(2.0, 0.0)});
  total += score_circle({false, {}, 0.0}, std::vector<TruthRing>{ring_at(0.0, 3.5)});
  total += score_circle({true, {3.0, 3.0}, 0.7}, std::vector<TruthRing>{ring_at(2.97, 2.97)});
  total += score_circle({true, {1.0, 1.0}, 0.75}, std::vector<TruthRing>{ring_at(7.0, 0.0)});
  total += score_circle({false, {}, 0.0}, std::vector<TruthRing>{ring_at(3.5, 0.0, 0.1)});
  EXPECT_EQ(total.truths, 4U);
  EXPECT_EQ(total.recalled, 2U);
  ASSERT_EQ(kRingDistanceBinsM.size(), 4U);  // 0-3, 3-4, 4-5, >= 5 m
  EXPECT_EQ(total.truths_by_distance, (std::array<std::size_t, 4>{1, 1, 1, 1}));
  EXPECT_EQ(total.recalled_by_distance, (std::array<std::size_t, 4>{1, 0, 1, 0}));
  EXPECT_EQ(total.detections, 3U) << "the false circle 7 m away counts against precision";
  EXPECT_EQ(total.true_positives, 2U);
}

TEST(CircleScore, ABinStartsAtItsDistance) {
  EXPECT_EQ(ring_distance_bin({2.999, 0.0}), 0U);
  EXPECT_EQ(ring_distance_bin({3.0, 0.0}), 1U);
  EXPECT_EQ(ring_distance_bin({0.0, -4.0}), 2U);
  EXPECT_EQ(ring_distance_bin({-30.0, 0.0}), 3U);
}

}  // namespace
}  // namespace ringlet::vision::evaluate
