#pragma once
// Where ringlet-train-hog gets its examples: labelled frames (a ringlet-dataset folder, or
// synthetic frames drawn here for a bootstrap model) and folders of cropped patches. Every
// window is cut with the detector's own placement (ball_window / robot_window) and resampler
// (resample_luma), so training sees exactly what inference will.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "ringlet/vision/hog_svm.hpp"
#include "proposals.hpp"
#include "ringlet/vision/resample.hpp"

namespace ringlet::vision::train {

/// An object's image box: x, y (top-left), w, h in px, (0, 0) the top-left pixel's corner.
struct Box {
  double x = 0, y = 0, w = 0, h = 0;
};

struct LabelledFrame {
  cv::Mat gray;               // 8-bit luminance
  std::vector<Box> objects;   // the target's boxes (positives)
  std::vector<Box> ignore;    // boxes of the target too hidden to be positives: no negatives there either
  std::vector<Proposal> proposals;  // the target detector's own candidate windows (proposals.hpp)
  std::string source;         // file name, for messages
};

/// The frames of a ringlet-dataset folder (frame_*.json with their images). Per frame JSON:
/// "image" (file name next to it) and, for the ball, "balls": [{"box": [x, y, w, h],
/// "visible_fraction": f (optional)}, ...] — or, from a dataset of before issue 10, "ball":
/// {"visible", "image_centre", "image_radius", "visible_fraction"}; for robots "robots":
/// [{"box": [x, y, w, h], "visible_fraction": f (optional)}]. Objects with a visible fraction
/// below `min_visible` are ignored. At most `max_frames` (0: all), in name order. ToolError naming
/// the file and the field when anything is missing or malformed.
[[nodiscard]] std::vector<LabelledFrame> load_dataset(const std::filesystem::path& dir, HogTarget target,
                                                      double min_visible, int max_frames);

/// `count` synthetic grey frames (320×240) with a carpet texture, lines and, for the target, 0–2
/// objects: a black-and-white ball (white disc, dark pentagon patches) or a NAO-like silhouette,
/// plus the other kind as clutter. Deterministic in (seed, index). For a BOOTSTRAP model only.
[[nodiscard]] std::vector<LabelledFrame> synthetic_frames(HogTarget target, std::uint64_t seed, int count);

/// Patches from DIR/pos/*.png and DIR/neg/*.png (any size with the window's aspect ratio within
/// 5 %; resampled to the window). ToolError when a folder is missing, empty, or an image wrong.
struct PatchSet {
  std::vector<std::vector<std::uint8_t>> positives, negatives;
};
[[nodiscard]] PatchSet load_patches(const std::filesystem::path& dir, const HogParams& hog);

/// The window the detector would classify for a true box.
[[nodiscard]] WindowPlacement truth_window(HogTarget target, const HogParams& hog, const Box& b);

/// Resamples a window of a grey image into a window-sized patch.
void cut_patch(const cv::Mat& gray, const WindowPlacement& w, const HogParams& hog, std::vector<std::uint8_t>& patch);

/// The window's frame rectangle (for overlap tests).
[[nodiscard]] Box window_box(const WindowPlacement& w, const HogParams& hog);
/// Intersection over the smaller box's area (0..1).
[[nodiscard]] double overlap(const Box& a, const Box& b);

}  // namespace ringlet::vision::train
