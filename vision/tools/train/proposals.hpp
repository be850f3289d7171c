#pragma once
// The detectors' own proposals in a dataset frame. At run time a classifier only ever sees the
// windows its detector proposes: round non-field blobs of a ball's size (balls, but also robots'
// feet, goal-post bases, line crossings) or non-field columns standing on the field (robots, but
// also posts, referees' legs, the goal's net), placed as the detector places them (a close
// robot's window reaches far above the picture). Training on true boxes and random windows alone
// leaves that clutter and that placement unseen, and makes the validation precision optimistic.
// So each training frame is also classified and run through the target's candidate stage, and
// every proposal becomes a sample: positive on a true object, negative away from every object.
#include <filesystem>
#include <vector>

#include <opencv2/core.hpp>

#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/vision/hog_svm.hpp"
#include "ringlet/vision/resample.hpp"

namespace ringlet::vision::train {

struct Proposal {
  WindowPlacement window{};
  hal::Pixel at{};     // the ball's centre, or the robot's foot point
  double size = 0.0;   // the expected ball radius there, or the robot's expected height (px)
};

/// The proposals of `target`'s detector in `bgr`, the picture of the ringlet-dataset frame
/// `frame_json` (its camera: intrinsics, mount, head), with the default colour (adaptive) and
/// level 0's strides. ToolError naming the file when its camera record is missing or malformed.
[[nodiscard]] std::vector<Proposal> detector_proposals(HogTarget target, const std::filesystem::path& frame_json,
                                                       const cv::Mat& bgr);

}  // namespace ringlet::vision::train
