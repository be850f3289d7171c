#pragma once
// The colour classes vision cares about, and the colour space it classifies in.
#include <cstdint>

#include "ringlet/hal/yuv.hpp"

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

// The camera's colour space and the one BGR → YUV conversion (full-range BT.601, fixed point),
// shared with the camera backends so a replayed frame classifies exactly like a live one.
using hal::Yuv;
using hal::bgr_to_yuv;

}  // namespace ringlet::vision
