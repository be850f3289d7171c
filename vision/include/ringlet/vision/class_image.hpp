#pragma once
// A frame classified into colour classes, one byte per pixel, full-resolution indexing.
//
// Only the part below the horizon is classified (rows from first_row on), and at sampling step
// `step` only pixels with x % step == 0 and (y − first_row) % step == 0 are; everything else keeps
// stale bytes and must not be read — every consumer walks the same grid (see sampled()).
#include <cmath>
#include <cstdint>
#include <vector>

#include "ringlet/hal/camera.hpp"
#include "ringlet/vision/colour.hpp"
#include "ringlet/vision/colour_table.hpp"
#include "ringlet/vision/field_colour.hpp"

namespace ringlet::vision {

class ClassImage {
 public:
  /// Allocates width × height bytes, once.
  ClassImage(int width, int height);

  [[nodiscard]] int width() const noexcept { return width_; }
  [[nodiscard]] int height() const noexcept { return height_; }
  [[nodiscard]] int first_row() const noexcept { return first_row_; }
  [[nodiscard]] int step() const noexcept { return step_; }
  [[nodiscard]] ColourClass at(int x, int y) const noexcept {
    return static_cast<ColourClass>(data_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)]);
  }
  [[nodiscard]] bool sampled(int x, int y) const noexcept {
    return y >= first_row_ && y < height_ && x >= 0 && x < width_ && x % step_ == 0 && (y - first_row_) % step_ == 0;
  }
  /// The class at image point (x, y), read from the sampled pixel of its step × step block;
  /// kOther outside the classified area. For consumers that work at sub-pixel positions.
  [[nodiscard]] ColourClass class_near(double x, double y) const noexcept {
    const int xi = static_cast<int>(std::floor(x));
    const int yi = static_cast<int>(std::floor(y));
    if (xi < 0 || xi >= width_ || yi < first_row_ || yi >= height_) return ColourClass::kOther;
    return at(xi / step_ * step_, first_row_ + (yi - first_row_) / step_ * step_);
  }
  [[nodiscard]] const std::uint8_t* row(int y) const noexcept {
    return data_.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width_);
  }

  /// Classifies rows [first_row, height) of `frame` (same size as this image, else returns false
  /// and classifies nothing) every `step` (1 or 2) pixels in both directions. YUYV pairs share
  /// their U and V; BGR8 goes through bgr_to_yuv; Gray8 is taken as U = V = 128.
  bool classify(const hal::FrameView& frame, const ColourTable& table, int first_row, int step) noexcept;
  /// The same with the adaptive classifier (built for this frame's size): per pixel one chroma
  /// table load (per YUYV pair), one luminance table load for the pixel's cell and one combining load.
  bool classify(const hal::FrameView& frame, const AdaptiveClassifier& adaptive, int first_row, int step) noexcept;

 private:
  int width_;
  int height_;
  int first_row_ = 0;
  int step_ = 1;
  std::vector<std::uint8_t> data_;
};

/// The luminance of pixel x of one row, per pixel format: what luma_at does after its switch,
/// for loops that pick the format once (resample.cpp) instead of per pixel.
[[nodiscard]] inline std::uint8_t yuyv_luma(const std::uint8_t* row, int x) noexcept {
  return row[2 * static_cast<std::size_t>(x)];
}
[[nodiscard]] inline std::uint8_t bgr_luma(const std::uint8_t* row, int x) noexcept {
  const std::uint8_t* p = row + 3 * static_cast<std::size_t>(x);
  return bgr_to_yuv(p[0], p[1], p[2]).y;
}
[[nodiscard]] inline std::uint8_t gray_luma(const std::uint8_t* row, int x) noexcept {
  return row[static_cast<std::size_t>(x)];
}

/// The luminance of pixel (x, y) of a frame (no bounds check).
[[nodiscard]] inline std::uint8_t luma_at(const hal::FrameView& f, int x, int y) noexcept {
  const std::uint8_t* row = f.data + static_cast<std::size_t>(y) * static_cast<std::size_t>(f.stride);
  switch (f.format) {
    case hal::PixelFormat::kYuyv: return yuyv_luma(row, x);
    case hal::PixelFormat::kBgr8: return bgr_luma(row, x);
    case hal::PixelFormat::kGray8: return gray_luma(row, x);
  }
  return 0;
}

/// Pixel (x, y) of a frame in YUV (no bounds check): YUYV pairs share their U and V (the last
/// pixel of an odd width has no V: 128), BGR8 goes through bgr_to_yuv, Gray8 has U = V = 128.
[[nodiscard]] inline Yuv yuv_at(const hal::FrameView& f, int x, int y) noexcept {
  const std::uint8_t* row = f.data + static_cast<std::size_t>(y) * static_cast<std::size_t>(f.stride);
  switch (f.format) {
    case hal::PixelFormat::kYuyv: {
      const std::uint8_t* pair = row + 4 * (static_cast<std::size_t>(x) / 2);
      return {yuyv_luma(row, x), pair[1], (x | 1) < f.width ? pair[3] : std::uint8_t{128}};
    }
    case hal::PixelFormat::kBgr8: {
      const std::uint8_t* p = row + 3 * static_cast<std::size_t>(x);
      return bgr_to_yuv(p[0], p[1], p[2]);
    }
    case hal::PixelFormat::kGray8: return {gray_luma(row, x), 128, 128};
  }
  return {};
}

}  // namespace ringlet::vision
