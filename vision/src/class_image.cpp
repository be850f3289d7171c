// Frame classification: one LUT load per classified pixel, plain loops the compiler can unroll.
#include <algorithm>

#include "ringlet/vision/class_image.hpp"

namespace ringlet::vision {
namespace {

// One YUYV row, for a table of Bits bits per channel known at compile time: the pixel pair's U and
// V part of the index is computed once, so each pixel costs one shift, one or and one load.
template <int Bits>
void classify_yuyv_row(const std::uint8_t* in, std::uint8_t* out, std::size_t w, const std::uint8_t* lut) noexcept {
  constexpr int kShift = 8 - Bits;
  for (std::size_t x = 0; x + 1 < w; x += 2) {
    const std::uint8_t* p = in + 2 * x;  // Y0 U Y1 V
    const std::size_t uv = (static_cast<std::size_t>(p[1] >> kShift) << Bits) | static_cast<std::size_t>(p[3] >> kShift);
    out[x] = lut[(static_cast<std::size_t>(p[0] >> kShift) << (2 * Bits)) | uv];
    out[x + 1] = lut[(static_cast<std::size_t>(p[2] >> kShift) << (2 * Bits)) | uv];
  }
}

using RowClassifier = void (*)(const std::uint8_t*, std::uint8_t*, std::size_t, const std::uint8_t*) noexcept;

RowClassifier yuyv_row_classifier(int bits) noexcept {
  switch (bits) {
    case 4: return classify_yuyv_row<4>;
    case 5: return classify_yuyv_row<5>;
    case 7: return classify_yuyv_row<7>;
    default: return classify_yuyv_row<6>;
  }
}

}  // namespace

ClassImage::ClassImage(int width, int height)
    : width_(std::max(width, 0)),
      height_(std::max(height, 0)),
      data_(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), 0) {}

bool ClassImage::classify(const hal::FrameView& frame, const ColourTable& table, int first_row, int step) noexcept {
  if (frame.width != width_ || frame.height != height_ || frame.data == nullptr) return false;
  step_ = step == 2 ? 2 : 1;
  first_row_ = std::clamp(first_row, 0, height_);
  const std::uint8_t* lut = table.data();
  const int bits = table.bin_bits();
  const int s = 8 - bits;
  const auto idx = [bits, s](unsigned y, unsigned u, unsigned v) {
    return (static_cast<std::size_t>(y >> s) << (2 * bits)) | (static_cast<std::size_t>(u >> s) << bits) |
           static_cast<std::size_t>(v >> s);
  };
  const auto w = static_cast<std::size_t>(width_);
  const RowClassifier yuyv_row = yuyv_row_classifier(bits);
  for (int y = first_row_; y < height_; y += step_) {
    const std::uint8_t* in = frame.data + static_cast<std::size_t>(y) * static_cast<std::size_t>(frame.stride);
    std::uint8_t* out = data_.data() + static_cast<std::size_t>(y) * w;
    switch (frame.format) {
      case hal::PixelFormat::kYuyv:
        if (step_ == 1) {
          yuyv_row(in, out, w, lut);
          if ((w & 1U) != 0) out[w - 1] = lut[idx(in[2 * (w - 1)], in[2 * (w - 1) + 1], 128)];
        } else {
          for (std::size_t x = 0; x < w; x += 2) {
            const std::uint8_t* p = in + 2 * x;
            out[x] = lut[idx(p[0], p[1], x + 1 < w ? p[3] : 128U)];
          }
        }
        break;
      case hal::PixelFormat::kBgr8:
        for (std::size_t x = 0; x < w; x += static_cast<std::size_t>(step_)) {
          const std::uint8_t* p = in + 3 * x;
          const Yuv c = bgr_to_yuv(p[0], p[1], p[2]);
          out[x] = lut[idx(c.y, c.u, c.v)];
        }
        break;
      case hal::PixelFormat::kGray8:
        for (std::size_t x = 0; x < w; x += static_cast<std::size_t>(step_)) out[x] = lut[idx(in[x], 128, 128)];
        break;
    }
  }
  return true;
}

bool ClassImage::classify(const hal::FrameView& frame, const AdaptiveClassifier& adaptive, int first_row, int step) noexcept {
  if (frame.width != width_ || frame.height != height_ || frame.data == nullptr) return false;
  if (adaptive.width() != width_ || adaptive.height() != height_) return false;
  step_ = step == 2 ? 2 : 1;
  first_row_ = std::clamp(first_row, 0, height_);
  const std::uint8_t* chroma = adaptive.chroma_table();
  const std::uint8_t* combine = adaptive.combine_table();
  const auto s = static_cast<std::size_t>(step_);
  const auto w = static_cast<std::size_t>(width_);
  for (int y = first_row_; y < height_; y += step_) {
    const std::uint8_t* in = frame.data + static_cast<std::size_t>(y) * static_cast<std::size_t>(frame.stride);
    std::uint8_t* out = data_.data() + static_cast<std::size_t>(y) * w;
    const int cell_row = (y * kColourCellsY / height_) * kColourCellsX;
    // Column segments of one cell each: x*cells/width == cx  <=>  x in [ceil(cx*w/cells), ceil((cx+1)*w/cells)).
    for (int cx = 0; cx < kColourCellsX; ++cx) {
      const std::uint8_t* luma = adaptive.luma_table(cell_row + cx);
      std::size_t xs = (static_cast<std::size_t>(cx) * w + kColourCellsX - 1) / kColourCellsX;
      const std::size_t xe = (static_cast<std::size_t>(cx + 1) * w + kColourCellsX - 1) / kColourCellsX;
      xs = (xs + s - 1) / s * s;  // the first sampled column of the segment
      switch (frame.format) {
        case hal::PixelFormat::kYuyv:
          if (step_ == 1 && (xs & 1U) == 0 && (xe & 1U) == 0) {
            // Whole pixel pairs: the chroma bits once per pair.
            for (std::size_t x = xs; x < xe; x += 2) {
              const std::uint8_t* p = in + 2 * x;  // Y0 U Y1 V
              const unsigned c = static_cast<unsigned>(chroma[AdaptiveClassifier::chroma_index(p[1], p[3])]) << AdaptiveClassifier::kBits;
              out[x] = combine[c | luma[p[0]]];
              out[x + 1] = combine[c | luma[p[2]]];
            }
          } else {
            for (std::size_t x = xs; x < xe; x += s) {
              const std::uint8_t* pair = in + 4 * (x / 2);
              const std::uint8_t v = (x | 1U) < w ? pair[3] : std::uint8_t{128};
              const unsigned c = static_cast<unsigned>(chroma[AdaptiveClassifier::chroma_index(pair[1], v)]) << AdaptiveClassifier::kBits;
              out[x] = combine[c | luma[in[2 * x]]];
            }
          }
          break;
        case hal::PixelFormat::kBgr8:
          for (std::size_t x = xs; x < xe; x += s) {
            const std::uint8_t* p = in + 3 * x;
            const Yuv q = bgr_to_yuv(p[0], p[1], p[2]);
            out[x] = combine[static_cast<unsigned>(chroma[AdaptiveClassifier::chroma_index(q.u, q.v)]) << AdaptiveClassifier::kBits | luma[q.y]];
          }
          break;
        case hal::PixelFormat::kGray8:
          for (std::size_t x = xs; x < xe; x += s) {
            out[x] = combine[static_cast<unsigned>(chroma[AdaptiveClassifier::chroma_index(128, 128)]) << AdaptiveClassifier::kBits | luma[in[x]]];
          }
          break;
      }
    }
  }
  return true;
}

}  // namespace ringlet::vision
