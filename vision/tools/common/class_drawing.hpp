#pragma once
// The colour classes drawn over the picture, so a person can see how the pixels were classified:
// field green, line white, ball orange, other darkened, and what was not classified (above the
// horizon) left as it is, dimmed.
#include <filesystem>

#include <opencv2/core.hpp>

#include "ringlet/vision/class_image.hpp"

namespace ringlet::vision::tools {

/// A copy of `bgr` (same size as `classes`) with the classes blended over it. At class step 2
/// every pixel takes the class of the sampled pixel at or above-left of it.
[[nodiscard]] cv::Mat draw_classes(const cv::Mat& bgr, const ClassImage& classes);

/// draw_classes written to `file` (the extension picks PNG or JPEG). On failure prints
/// "<tool>: <file>: cannot write the class image ..." to stderr and returns false.
[[nodiscard]] bool write_class_image(const std::filesystem::path& file, const cv::Mat& bgr, const ClassImage& classes,
                                     const char* tool);

}  // namespace ringlet::vision::tools
