// The evaluation's frame identities: a set is described by its seeds and index ranges, and two
// sets overlap when a frame shares generator, seed and index, or its pixels, with the other.
#include "frame_identity.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "vision_io.hpp"

namespace ringlet::vision::evaluate {
namespace {

FrameId id(std::uint64_t seed, std::uint64_t index, std::uint64_t pixels, int version = 2) {
  return {"frame_" + std::to_string(index) + ".json", version, seed, index, pixels};
}

TEST(FrameIdentity, DescribeGivesSeedsAndIndexRanges) {
  FrameSet s{"test set", "/data/test", {id(7, 0, 1), id(7, 1, 2), id(7, 2, 3), id(7, 5, 4), id(9, 3, 5, 1)}};
  EXPECT_EQ(s.describe(), "/data/test: 5 frames, seed 9 (generator v1) frames 3, seed 7 (generator v2) frames 0-2, 5");
}

TEST(FrameIdentity, DisjointSetsDoNotOverlap) {
  const FrameSet a{"tuning set", "a", {id(1, 0, 10), id(1, 1, 11)}};
  const FrameSet b{"test set", "b", {id(2, 0, 20), id(2, 1, 21), id(1, 0, 10, 1)}};  // seed 1 frame 0 of another generator
  EXPECT_FALSE(find_overlap(a, {"test set", "b", {id(2, 0, 20), id(2, 1, 21)}}).any());
  // Same seed and index but another generator and other pixels: another frame.
  const Overlap o = find_overlap(a, {"test set", "b", {id(1, 0, 99, 1)}});
  EXPECT_FALSE(o.any());
  EXPECT_NO_THROW(require_disjoint(a, {"test set", "b", {id(2, 0, 20)}}));
  (void)b;
}

TEST(FrameIdentity, SameDrawsOrSamePixelsOverlap) {
  const FrameSet tune{"tuning set", "a", {id(1, 0, 10), id(1, 1, 11), id(1, 2, 12)}};
  const Overlap draws = find_overlap(tune, {"test set", "b", {id(1, 2, 12), id(1, 3, 13)}});
  EXPECT_EQ(draws.same_draws, 1U);
  EXPECT_EQ(draws.same_pixels, 1U);
  EXPECT_EQ(draws.example, "tuning set frame_2.json and test set frame_2.json are both seed 1 frame 2");
  // A copied picture under another seed and name is caught by its pixels alone.
  const Overlap copy = find_overlap(tune, {"test set", "b", {id(5, 0, 11)}});
  EXPECT_EQ(copy.same_draws, 0U);
  EXPECT_EQ(copy.same_pixels, 1U);
  EXPECT_EQ(copy.example, "tuning set frame_1.json and test set frame_0.json have identical pixels");
  try {
    require_disjoint(tune, {"test set", "b", {id(5, 0, 11)}});
    FAIL() << "no error";
  } catch (const tools::ToolError& e) {
    EXPECT_NE(std::string(e.what()).find("the tuning set and the test set overlap: 0 frames of the test set have the "
                                         "seed and index of a tuning set frame, 1 have identical pixels"),
              std::string::npos) << e.what();
  }
}

TEST(FrameIdentity, PixelHashSeesEveryPixelAndTheSize) {
  cv::Mat a(4, 6, CV_8UC3, cv::Scalar(1, 2, 3));
  cv::Mat b = a.clone();
  EXPECT_EQ(pixel_hash(a), pixel_hash(b));
  b.at<cv::Vec3b>(3, 5)[2] = 4;
  EXPECT_NE(pixel_hash(a), pixel_hash(b));
  EXPECT_NE(pixel_hash(a), pixel_hash(a.reshape(3, 6)));  // same bytes, another shape
  EXPECT_EQ(pixel_hash(a(cv::Rect(0, 0, 3, 2))), pixel_hash(a(cv::Rect(0, 0, 3, 2)).clone()));  // a view: rows, not the stride
}

}  // namespace
}  // namespace ringlet::vision::evaluate
