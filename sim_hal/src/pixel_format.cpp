// BT.601 in 8-bit fixed point (the coefficients every V4L2 driver documents), so a frame converts
// to the same bytes on x86 and ARM.
#include "ringlet/sim/pixel_format.hpp"

#include <cstddef>

namespace ringlet::sim {
namespace {

std::uint8_t clamp_byte(int value) noexcept {
  return static_cast<std::uint8_t>(value < 0 ? 0 : (value > 255 ? 255 : value));
}

// Inputs are sums of `n` pixels' channels; the shift divides by 256·n (n = 1 or 2).
int luma(int b, int g, int r) noexcept { return ((66 * r + 129 * g + 25 * b + 128) >> 8) + 16; }
int chroma_u(int b, int g, int r, int shift) noexcept {
  return ((-38 * r - 74 * g + 112 * b + (1 << (shift - 1))) >> shift) + 128;
}
int chroma_v(int b, int g, int r, int shift) noexcept {
  return ((112 * r - 94 * g - 18 * b + (1 << (shift - 1))) >> shift) + 128;
}

}  // namespace

Yuv bgr_to_yuv(std::uint8_t b, std::uint8_t g, std::uint8_t r) noexcept {
  return {clamp_byte(luma(b, g, r)), clamp_byte(chroma_u(b, g, r, 8)), clamp_byte(chroma_v(b, g, r, 8))};
}

void bgr_to_yuyv(std::span<const std::uint8_t> bgr, int width, int height, std::span<std::uint8_t> yuyv) noexcept {
  const auto pairs = static_cast<std::size_t>(width / 2) * static_cast<std::size_t>(height);
  const std::uint8_t* in = bgr.data();
  std::uint8_t* out = yuyv.data();
  for (std::size_t i = 0; i < pairs; ++i, in += 6, out += 4) {
    const int b0 = in[0], g0 = in[1], r0 = in[2];
    const int b1 = in[3], g1 = in[4], r1 = in[5];
    out[0] = clamp_byte(luma(b0, g0, r0));
    out[1] = clamp_byte(chroma_u(b0 + b1, g0 + g1, r0 + r1, 9));
    out[2] = clamp_byte(luma(b1, g1, r1));
    out[3] = clamp_byte(chroma_v(b0 + b1, g0 + g1, r0 + r1, 9));
  }
}

}  // namespace ringlet::sim
