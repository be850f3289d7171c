#pragma once
// One colour conversion for everything that turns BGR into the NAO's YUYV (ITU-R BT.601, full
// range, as V4L2 cameras deliver it): camera backends and tools agree on it byte for byte.
#include <cstddef>
#include <cstdint>
#include <span>

namespace ringlet::hal {

struct Yuv {
  std::uint8_t y = 0;
  std::uint8_t u = 128;
  std::uint8_t v = 128;
};

/// BT.601 full range, rounded to nearest, clamped.
[[nodiscard]] inline constexpr Yuv bgr_to_yuv(std::uint8_t b, std::uint8_t g, std::uint8_t r) noexcept {
  // Fixed point (x 2^16) keeps it exact and identical on every host.
  const std::int32_t y = (19595 * r + 38470 * g + 7471 * b + 32768) >> 16;
  const std::int32_t u = ((-11059 * r - 21709 * g + 32768 * b + 32768) >> 16) + 128;
  const std::int32_t v = ((32768 * r - 27439 * g - 5329 * b + 32768) >> 16) + 128;
  const auto clamp = [](std::int32_t x) { return static_cast<std::uint8_t>(x < 0 ? 0 : (x > 255 ? 255 : x)); };
  return {clamp(y), clamp(u), clamp(v)};
}

/// One row of `width` BGR pixels (width even) to YUYV: Y0 U Y1 V per pixel pair, chroma averaged.
inline void bgr_row_to_yuyv(const std::uint8_t* bgr, std::uint8_t* yuyv, int width) noexcept {
  for (int x = 0; x + 1 < width; x += 2) {
    const Yuv a = bgr_to_yuv(bgr[0], bgr[1], bgr[2]);
    const Yuv b = bgr_to_yuv(bgr[3], bgr[4], bgr[5]);
    yuyv[0] = a.y;
    yuyv[1] = static_cast<std::uint8_t>((a.u + b.u + 1) / 2);
    yuyv[2] = b.y;
    yuyv[3] = static_cast<std::uint8_t>((a.v + b.v + 1) / 2);
    bgr += 6;
    yuyv += 4;
  }
}

/// A whole BGR image (width·height·3 bytes, rows packed) to YUYV (width·height·2 bytes).
inline void bgr_to_yuyv(std::span<const std::uint8_t> bgr, int width, int height, std::span<std::uint8_t> yuyv) noexcept {
  const auto w = static_cast<std::size_t>(width);
  for (std::size_t row = 0; row < static_cast<std::size_t>(height); ++row) {
    bgr_row_to_yuyv(bgr.data() + row * w * 3, yuyv.data() + row * w * 2, width);
  }
}

}  // namespace ringlet::hal
