#pragma once
// Which frames an evaluation used, so that "tuned on one set, reported on another" can be checked
// rather than claimed. A frame is identified twice over: by its draws — ringlet-dataset's
// generator version, seed and frame index, which decide everything it rendered — and by its
// content — a hash of the decoded pixels, which catches the same picture under another name,
// seed or folder. Two sets overlap when any frame matches on either.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "dataset_frame.hpp"

namespace ringlet::vision::evaluate {

struct FrameId {
  std::filesystem::path json;
  int generator_version = 1;
  std::uint64_t seed = 0;
  std::uint64_t index = 0;
  std::uint64_t pixels = 0;  // pixel_hash of the picture
};

struct FrameSet {
  std::string role;    // "tuning set", "test set", "excluded set"
  std::string folder;
  std::vector<FrameId> frames;

  /// "<folder>: N frames, seed S (generator vG) frames a-b[, c-d]" (one clause per seed).
  [[nodiscard]] std::string describe() const;
};

/// FNV-1a (64 bit) over the image's size and BGR bytes: equal pictures, equal hashes, whatever
/// the file was called or how it was compressed.
[[nodiscard]] std::uint64_t pixel_hash(const cv::Mat& bgr);

[[nodiscard]] FrameId frame_id(const DatasetFrame& frame, const cv::Mat& bgr);

struct Overlap {
  std::size_t same_draws = 0;   // frames of `b` with a frame of `a` of equal generator, seed and index
  std::size_t same_pixels = 0;  // frames of `b` with a frame of `a` of equal pixels
  std::string example;          // the first pair found
  [[nodiscard]] bool any() const noexcept { return same_draws + same_pixels > 0; }
};

[[nodiscard]] Overlap find_overlap(const FrameSet& a, const FrameSet& b);

/// ToolError naming both sets, the counts and an example when they share a frame.
void require_disjoint(const FrameSet& a, const FrameSet& b);

}  // namespace ringlet::vision::evaluate
