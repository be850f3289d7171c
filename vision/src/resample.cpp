// Bilinear luminance resampling into a fixed window (resample.hpp).
#include "ringlet/vision/resample.hpp"

#include <algorithm>
#include <cmath>

#include "ringlet/vision/class_image.hpp"

namespace ringlet::vision {
namespace {

// Luminance at a position in 1/256 px where integer positions are pixel centres, clamped to the
// frame; the result is scaled by 65536.
int sample_fixed(const hal::FrameView& f, std::int64_t fx, std::int64_t fy) noexcept {
  fx = std::clamp<std::int64_t>(fx, 0, static_cast<std::int64_t>(f.width - 1) * 256);
  fy = std::clamp<std::int64_t>(fy, 0, static_cast<std::int64_t>(f.height - 1) * 256);
  const int x0 = static_cast<int>(fx >> 8);
  const int y0 = static_cast<int>(fy >> 8);
  const int ax = static_cast<int>(fx & 255);
  const int ay = static_cast<int>(fy & 255);
  const int x1 = std::min(x0 + 1, f.width - 1);
  const int y1 = std::min(y0 + 1, f.height - 1);
  const int top = luma_at(f, x0, y0) * (256 - ax) + luma_at(f, x1, y0) * ax;
  const int bottom = luma_at(f, x0, y1) * (256 - ax) + luma_at(f, x1, y1) * ax;
  return top * (256 - ay) + bottom * ay;
}

// A frame coordinate (pixel-centre convention: pixel i's centre at i + ½) as fixed point with
// pixel centres at integers; far-off values are clamped before the conversion (no overflow).
std::int64_t to_fixed(double v) noexcept {
  const double c = std::clamp(v - 0.5, -1.0e6, 1.0e6);
  return static_cast<std::int64_t>(std::floor(c * 256.0 + 0.5));
}

}  // namespace

void resample_luma(const hal::FrameView& frame, double left, double top, double scale, int out_width, int out_height,
                   std::span<std::uint8_t> out) noexcept {
  if (out_width <= 0 || out_height <= 0 || !(scale > 0.0) || frame.data == nullptr || frame.width < 1 ||
      frame.height < 1 || out.size() < static_cast<std::size_t>(out_width) * static_cast<std::size_t>(out_height)) {
    return;
  }
  const bool smooth = scale >= 2.0;
  const double q = scale / 4.0;
  for (int i = 0; i < out_height; ++i) {
    const double y = top + (static_cast<double>(i) + 0.5) * scale;
    for (int j = 0; j < out_width; ++j) {
      const double x = left + (static_cast<double>(j) + 0.5) * scale;
      int value = 0;
      if (smooth) {
        const std::int64_t s = sample_fixed(frame, to_fixed(x - q), to_fixed(y - q)) +
                               static_cast<std::int64_t>(sample_fixed(frame, to_fixed(x + q), to_fixed(y - q))) +
                               sample_fixed(frame, to_fixed(x - q), to_fixed(y + q)) +
                               sample_fixed(frame, to_fixed(x + q), to_fixed(y + q));
        value = static_cast<int>((s + 2 * 65536) / (4 * 65536));
      } else {
        value = (sample_fixed(frame, to_fixed(x), to_fixed(y)) + 32768) / 65536;
      }
      out[static_cast<std::size_t>(i * out_width + j)] = static_cast<std::uint8_t>(std::clamp(value, 0, 255));
    }
  }
}

}  // namespace ringlet::vision
