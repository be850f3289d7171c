#pragma once
// Labelled example images: a picture and, next to it, NAME_labels.png, one byte per pixel holding
// the ColourClass of that pixel (0 other, 1 field, 2 line, 3 ball), as ringlet-dataset writes them
// (or as a person paints them); 255 means "not labelled" (ignored: partial labels are fine). Samples are taken as the robot's camera would give them: the
// picture goes through hal::bgr_to_yuyv, so a pixel pair shares its chroma.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include "ringlet/vision/colour_table.hpp"

namespace ringlet::vision::tools {

/// The label value of a pixel nobody labelled: it neither trains a table nor is scored.
inline constexpr std::uint8_t kIgnoreLabel = 255;

struct LabelledImage {
  std::filesystem::path picture;
  std::filesystem::path labels;
};

/// Every *_labels.png in `dir` (sorted by name) with its picture (NAME.png, else NAME.jpg /
/// .jpeg). ToolError when the folder does not exist, holds no label files, or a picture is missing.
[[nodiscard]] std::vector<LabelledImage> find_labelled_images(const std::filesystem::path& dir);

/// Samples of every `stride`-th pixel in both directions (offset so that neighbouring pixel pairs
/// alternate). ToolError naming the file when an image cannot be read, the sizes differ or a
/// label is not a colour class.
void sample_labelled_image(const LabelledImage& image, int stride, std::vector<LabelledSample>& out);

/// All of them, calling `progress(done, total)` after each image.
[[nodiscard]] std::vector<LabelledSample> sample_labelled_set(const std::vector<LabelledImage>& images, int stride,
                                                              const std::function<void(std::size_t, std::size_t)>& progress);

}  // namespace ringlet::vision::tools
