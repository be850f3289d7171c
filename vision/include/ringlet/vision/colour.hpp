#pragma once
// The colour classes vision cares about and the one colour conversion it does (BGR → YUV).
#include <cstdint>

namespace ringlet::vision {

/// What a pixel is taken to be. Stored as one byte per pixel in the class image and the LUT.
enum class ColourClass : std::uint8_t { kOther = 0, kField = 1, kLine = 2, kBall = 3 };
inline constexpr int kColourClassCount = 4;

[[nodiscard]] constexpr const char* to_string(ColourClass c) noexcept {
  switch (c) {
    case ColourClass::kOther: return "other";
    case ColourClass::kField: return "field";
    case ColourClass::kLine: return "line";
    case ColourClass::kBall: return "ball";
  }
  return "?";
}

struct Yuv {
  std::uint8_t y = 0;
  std::uint8_t u = 128;
  std::uint8_t v = 128;
};

/// Full-range (JFIF) BT.601, the convention of the camera's YUYV: Y = 0.299 R + 0.587 G + 0.114 B,
/// U = 128 + 0.564 (B − Y), V = 128 + 0.713 (R − Y). Fixed point (16 fractional bits, rounded) so
/// every target gives the same bytes.
[[nodiscard]] constexpr Yuv bgr_to_yuv(std::uint8_t b, std::uint8_t g, std::uint8_t r) noexcept {
  const std::int32_t ri = r, gi = g, bi = b;
  constexpr std::int32_t kHalf = 1 << 15;
  constexpr std::int32_t kOffset = (128 << 16) + kHalf;
  const std::int32_t y = (19595 * ri + 38470 * gi + 7471 * bi + kHalf) >> 16;
  std::int32_t u = (-11059 * ri - 21709 * gi + 32768 * bi + kOffset) >> 16;
  std::int32_t v = (32768 * ri - 27439 * gi - 5329 * bi + kOffset) >> 16;
  u = u < 0 ? 0 : (u > 255 ? 255 : u);
  v = v < 0 ? 0 : (v > 255 ? 255 : v);
  return {static_cast<std::uint8_t>(y), static_cast<std::uint8_t>(u), static_cast<std::uint8_t>(v)};
}

}  // namespace ringlet::vision
