// The evaluation's matching rule (vision/tools/evaluate/segment_match.hpp) on hand-made cases.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "segment_match.hpp"

namespace ringlet::vision::evaluate {
namespace {

TEST(SegmentMatch, ExactDetectionIsPerfect) {
  const std::vector<TruthSegment> truth{{{0, 0, 100, 0}, 0.0}};
  const std::vector<Segment2> same{{0, 0, 100, 0}};
  const auto c = match_segments(same, truth);
  EXPECT_EQ(c.detections, 1U);
  EXPECT_EQ(c.true_positives, 1U);
  EXPECT_EQ(c.recalled, 1U);
  EXPECT_DOUBLE_EQ(c.f1(), 1.0);
  EXPECT_DOUBLE_EQ(c.mean_angle_error_deg(), 0.0);
  EXPECT_DOUBLE_EQ(c.mean_extent_error_px(), 0.0);
}

TEST(SegmentMatch, FragmentsArePreciseButOnlyCoverageEarnsRecall) {
  const std::vector<TruthSegment> truth{{{0, 0, 100, 0}, 0.0}, {{0, 50, 100, 50}, 0.0}};
  // Two fragments covering 40 % of the first line: precise, not enough to recall it.
  const std::vector<Segment2> few{{0, 1, 20, 1}, {50, -1, 70, -1}};
  auto c = match_segments(few, truth);
  EXPECT_EQ(c.true_positives, 2U);
  EXPECT_EQ(c.recalled, 0U);
  EXPECT_DOUBLE_EQ(c.precision(), 1.0);
  // Three overlapping fragments covering 0..60: recalled, extent error (0 + 40) / 2 = 20 px.
  const std::vector<Segment2> more{{0, 1, 30, 1}, {20, 0, 45, 0}, {40, -1, 60, -1}};
  c = match_segments(more, truth);
  EXPECT_EQ(c.recalled, 1U);
  EXPECT_DOUBLE_EQ(c.recall(), 0.5);
  EXPECT_DOUBLE_EQ(c.mean_extent_error_px(), 20.0);
  EXPECT_NEAR(c.mean_endpoint_error_px(), (1.0 + 0.0 + 1.0) / 3.0, 1e-12);
}

TEST(SegmentMatch, WrongAngleOrOffsetIsAFalsePositive) {
  const std::vector<TruthSegment> truth{{{0, 0, 100, 0}, 0.0}};
  const std::vector<Segment2> tilted{{0, 0, 100, 10}};  // 5.7 degrees, far end 10 px off
  const std::vector<Segment2> offset{{0, 9, 100, 9}};   // parallel, 9 px away
  const std::vector<Segment2> close{{0, 3, 100, -3}};   // 3.4 degrees, within 8 px: a match
  EXPECT_EQ(match_segments(tilted, truth).true_positives, 0U);
  EXPECT_EQ(match_segments(offset, truth).true_positives, 0U);
  EXPECT_EQ(match_segments(offset, truth).detections, 1U);
  const auto c = match_segments(close, truth);
  EXPECT_EQ(c.true_positives, 1U);
  EXPECT_NEAR(c.mean_angle_error_deg(), 3.43, 0.01);
}

TEST(SegmentMatch, ReversedDirectionMatchesAndShortTruthsAreDontCare) {
  const std::vector<TruthSegment> truth{{{100, 0, 0, 0}, 0.0}, {{200, 200, 210, 200}, 0.0}};  // 10 px: don't care
  const std::vector<Segment2> detected{{0, 0, 100, 0}, {200, 201, 209, 201}};
  const auto c = match_segments(detected, truth);
  EXPECT_EQ(c.truths, 1U);
  EXPECT_EQ(c.detections, 1U) << "the detection of the don't-care segment is not scored";
  EXPECT_EQ(c.recalled, 1U);
}

TEST(SegmentMatch, AWideLineAcceptsItsBordersAsWellAsItsCentre) {
  const std::vector<TruthSegment> wide{{{0, 0, 100, 0}, 12.0}};  // 24 px wide near the camera
  const std::vector<Segment2> border{{0, 12, 100, 12}};        // an edge detector's find
  EXPECT_EQ(match_segments(border, wide).true_positives, 1U);
  const std::vector<TruthSegment> thin{{{0, 0, 100, 0}, 1.0}};
  EXPECT_EQ(match_segments(border, thin).true_positives, 0U);
}

TEST(SegmentMatch, AFitThroughAnOccluderMatchesTheMarkingAndRecallsItsPieces) {
  // One painted line hidden by the ball between x = 40 and 60: two pieces of marking 3, and a
  // short piece of another marking (7) beyond its end, on the same straight line.
  const std::vector<TruthSegment> truth{
      {{0, 0, 40, 0}, 1.0, 3}, {{60, 0, 100, 0}, 1.0, 3}, {{130, 0, 200, 0}, 1.0, 7}};
  const std::vector<Segment2> through{{0, 1, 100, 1}};
  auto c = match_segments(through, truth);
  EXPECT_EQ(c.detections, 1U);
  EXPECT_EQ(c.true_positives, 1U);
  EXPECT_EQ(c.truths, 3U);
  EXPECT_EQ(c.recalled, 2U) << "both pieces of marking 3, not marking 7";
  // Reaching on to the next marking is reaching past this line's visible end: no match.
  const std::vector<Segment2> too_long{{0, 0, 200, 0}};
  c = match_segments(too_long, truth);
  EXPECT_EQ(c.true_positives, 0U);
  EXPECT_EQ(c.recalled, 0U);
  // Without markings (-1) every piece stands alone, as before: the fit through the ball misses both.
  std::vector<TruthSegment> unmarked = truth;
  for (TruthSegment& t : unmarked) t.marking = -1;
  c = match_segments(through, unmarked);
  EXPECT_EQ(c.true_positives, 0U);
}

TEST(SegmentMatch, RecallIsAlsoCountedByThePaintsWidthInThePicture) {
  // Half widths 0.5, 1.5, 3 and 6 px: paint 1, 3, 6 and 12 px wide, one truth in each bucket.
  const std::vector<TruthSegment> truth{
      {{0, 0, 100, 0}, 0.5}, {{0, 50, 100, 50}, 1.5}, {{0, 100, 100, 100}, 3.0}, {{0, 200, 100, 200}, 6.0}};
  const std::vector<Segment2> found{{0, 0, 100, 0}, {0, 200, 100, 200}};  // the thinnest and the widest
  const auto c = match_segments(found, truth);
  EXPECT_EQ(c.truths_by_width, (std::array<std::size_t, 4>{1, 1, 1, 1}));
  EXPECT_EQ(c.recalled_by_width, (std::array<std::size_t, 4>{1, 0, 0, 1}));
  EXPECT_EQ(width_bucket(0.99), 0U);  // 1.98 px
  EXPECT_EQ(width_bucket(1.0), 1U);   // 2 px: the next bucket starts there
  EXPECT_EQ(width_bucket(100.0), 3U);
  MatchCounts sum = c;
  sum += c;
  EXPECT_EQ(sum.truths_by_width[3], 2U);
  EXPECT_EQ(sum.recalled_by_width[0], 2U);
}

TEST(SegmentMatch, CountsAddUp) {
  MatchCounts a;
  a.detections = 2;
  a.true_positives = 1;
  a.truths = 4;
  a.recalled = 2;
  MatchCounts b = a;
  b += a;
  EXPECT_EQ(b.detections, 4U);
  EXPECT_DOUBLE_EQ(b.precision(), 0.5);
  EXPECT_DOUBLE_EQ(b.recall(), 0.5);
  EXPECT_DOUBLE_EQ(b.f1(), 0.5);
}

}  // namespace
}  // namespace ringlet::vision::evaluate
