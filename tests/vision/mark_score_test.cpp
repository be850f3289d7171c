// The marks' score (vision/tools/evaluate/mark_score.hpp): a found centre near a cross is right
// once, one near a small cross is neither right nor wrong, one near nothing is wrong.
#include <gtest/gtest.h>

#include <vector>

#include "mark_score.hpp"

namespace ringlet::vision::evaluate {
namespace {

TEST(MarkScore, NearestCrossWithinToleranceOnceAndSmallCrossesDoNotCount) {
  const std::vector<TruthMark> truth{{{1.0, 0.0}, 40.0}, {{3.0, 1.0}, 12.0}};  // the second is too small to expect
  EXPECT_EQ(score_marks({}, truth).truths, 1U);
  const std::vector<hal::RobotPoint> right{{1.05, 0.0}};
  CircleCounts c = score_marks(right, truth);
  EXPECT_EQ(c.detections, 1U);
  EXPECT_EQ(c.true_positives, 1U);
  EXPECT_EQ(c.recalled, 1U);
  EXPECT_NEAR(c.mean_centre_error_m(), 0.05, 1e-12);
  const std::vector<hal::RobotPoint> twice{{1.05, 0.0}, {0.98, 0.0}};
  c = score_marks(twice, truth);
  EXPECT_EQ(c.detections, 2U) << "the cross matches once; the second report is a false positive";
  EXPECT_EQ(c.true_positives, 1U);
  EXPECT_NEAR(c.mean_centre_error_m(), 0.02, 1e-12) << "nearest first";
  const std::vector<hal::RobotPoint> small{{3.0, 1.05}};
  c = score_marks(small, truth);
  EXPECT_EQ(c.detections, 0U) << "matching only a don't-care cross: left out";
  EXPECT_EQ(c.recalled, 0U);
  const std::vector<hal::RobotPoint> wrong{{1.2, 0.0}};
  c = score_marks(wrong, truth);
  EXPECT_EQ(c.detections, 1U);
  EXPECT_EQ(c.true_positives, 0U);
  EXPECT_DOUBLE_EQ(c.precision(), 0.0);
}

}  // namespace
}  // namespace ringlet::vision::evaluate
