#pragma once
// The ball detector's own proposals in a dataset frame. At run time the classifier only ever sees
// the windows BwBallDetector proposes (round non-field blobs of the expected size: balls, but
// also robots' feet, goal-post bases, line crossings, shadows); training on random windows alone
// leaves that clutter unseen and makes the validation precision optimistic. So each training
// frame is also run through the pipeline's classification and the candidate stage, and every
// proposal becomes a sample: positive on a true ball, negative away from every ball.
#include <filesystem>
#include <vector>

#include <opencv2/core.hpp>

#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/vision/resample.hpp"

namespace ringlet::vision::train {

struct Proposal {
  WindowPlacement window{};
  hal::Pixel centre{};
  double radius = 0.0;  // the expected ball radius there (px)
};

/// The proposals of `bgr`, the picture of the ringlet-dataset frame `frame_json` (its camera:
/// intrinsics, mount, head), with the default colour (adaptive) and level 0's ball stride.
/// ToolError naming the file when its camera record is missing or malformed.
[[nodiscard]] std::vector<Proposal> ball_proposals(const std::filesystem::path& frame_json, const cv::Mat& bgr);

}  // namespace ringlet::vision::train
