#pragma once
// A window of a frame's luminance resampled into a small fixed buffer (the HOG window), the same
// way on the robot and in the offline trainer, so that training and inference see equal patches.
#include <cstdint>
#include <span>

#include "ringlet/hal/camera.hpp"

namespace ringlet::vision {

/// Where a HOG window lies in the frame: top-left corner and frame px per window px.
struct WindowPlacement {
  double left = 0.0;
  double top = 0.0;
  double scale = 1.0;
};

/// Resamples the square-pixel window whose top-left corner is (left, top) (frame pixels, (0, 0)
/// the top-left corner of the top-left pixel) and whose output pixels are `scale` frame pixels
/// wide into `out` (out_width × out_height, row-major): output pixel (i, j) is the luminance at
/// (left + (j + ½)·scale, top + (i + ½)·scale), bilinear with 8-bit fixed-point weights. When
/// scale ≥ 2 each output pixel averages four such samples ±scale/4 around it (a cheap low-pass, so
/// that a large window does not alias). Positions outside the frame take the nearest border pixel.
/// Only the coordinates are floating point (basic operations); the rest is integer arithmetic, so
/// every target gives the same bytes. Does nothing if `out` is too small or scale ≤ 0.
void resample_luma(const hal::FrameView& frame, double left, double top, double scale, int out_width, int out_height,
                   std::span<std::uint8_t> out) noexcept;

}  // namespace ringlet::vision
