// What the camera adds after the optics: motion blur (the head moved while the rolling shutter
// exposed: a box filter along rows or columns) and sensor noise (per pixel and channel, new every
// frame). Only for the SPL look; both work in place on bgr_ with one preallocated line buffer.
#include <algorithm>

#include "camera_shading.hpp"
#include "render_math.hpp"
#include "ringlet/sim_hal/camera_renderer.hpp"

namespace ringlet::sim_hal {
namespace {

/// Box-filters `count` pixels (3 channels each, `stride` bytes apart) in place over `length`
/// pixels centred on each, clamping at the ends. `copy` holds at least 3·count bytes.
void box_blur(std::uint8_t* first, std::size_t stride, int count, int length, std::uint8_t* copy) noexcept {
  for (int i = 0; i < count; ++i) {
    const std::uint8_t* p = first + static_cast<std::size_t>(i) * stride;
    copy[3 * i] = p[0];
    copy[3 * i + 1] = p[1];
    copy[3 * i + 2] = p[2];
  }
  const int before = (length - 1) / 2;
  for (int c = 0; c < 3; ++c) {
    int sum = 0;
    for (int j = -before; j < length - before; ++j) sum += copy[3 * std::clamp(j, 0, count - 1) + c];
    for (int i = 0; i < count; ++i) {
      first[static_cast<std::size_t>(i) * stride + static_cast<std::size_t>(c)] =
          static_cast<std::uint8_t>((sum + length / 2) / length);
      sum += copy[3 * std::clamp(i + length - before, 0, count - 1) + c] - copy[3 * std::clamp(i - before, 0, count - 1) + c];
    }
  }
}

}  // namespace

void CameraRenderer::post_process() noexcept {
  const CameraLook& look = world_.look;
  const int width = spec_.intrinsics.width;
  const int height = spec_.intrinsics.height;
  const std::size_t row = static_cast<std::size_t>(width) * 3U;
  if (look.blur >= 2) {
    if (look.blur_vertical) {
      for (int u = 0; u < width; ++u) {
        box_blur(bgr_.data() + static_cast<std::size_t>(u) * 3U, row, height, look.blur, line_buffer_.data());
      }
    } else {
      for (int v = 0; v < height; ++v) {
        box_blur(bgr_.data() + static_cast<std::size_t>(v) * row, 3U, width, look.blur, line_buffer_.data());
      }
    }
  }
  if (!(look.noise > 0.0)) return;
  // Triangular noise per channel: the sum of two 5-bit fields of one hash per pixel, centred,
  // times the amplitude in 1/256 grey levels per step (integers: cheap, and exact everywhere).
  const int amplitude = static_cast<int>(look.noise * (256.0 / 31.0) + 0.5);
  const std::uint32_t frame_seed = seed_ ^ detail::hash2(static_cast<int>(frame_ & 0x7fffffffU), 0x5e05, 0x9a1dU);
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::uint8_t* p = bgr_.data();
  for (std::size_t i = 0; i < pixels; ++i, p += 3) {
    const std::uint32_t h = detail::hash2(static_cast<int>(i), 0x6e6f, frame_seed);
    for (int c = 0; c < 3; ++c) {
      const int a = static_cast<int>((h >> (10 * c)) & 31U);
      const int b = static_cast<int>((h >> (10 * c + 5)) & 31U);
      const int value = (static_cast<int>(p[c]) * 256 + amplitude * (a + b - 31) + 128) >> 8;  // floor: C++20
      p[c] = static_cast<std::uint8_t>(std::clamp(value, 0, 255));
    }
  }
}

}  // namespace ringlet::sim_hal
