#pragma once
// BGR8 to the NAO camera's YUYV (4:2:2), ITU-R BT.601 studio range (Y 16..235, U/V 16..240).
// Two neighbouring pixels share one U and one V, computed from their average colour; a row packs
// as Y0 U Y1 V per pixel pair, so width must be even.
#include <cstdint>
#include <span>

namespace ringlet::sim {

struct Yuv {
  std::uint8_t y = 0;
  std::uint8_t u = 0;
  std::uint8_t v = 0;
};

/// BT.601 studio-range conversion of one colour (integer arithmetic, exact on every target).
[[nodiscard]] Yuv bgr_to_yuv(std::uint8_t b, std::uint8_t g, std::uint8_t r) noexcept;

/// `bgr` holds width·height·3 bytes, `yuyv` receives width·height·2 bytes. width must be even.
void bgr_to_yuyv(std::span<const std::uint8_t> bgr, int width, int height, std::span<std::uint8_t> yuyv) noexcept;

}  // namespace ringlet::sim
