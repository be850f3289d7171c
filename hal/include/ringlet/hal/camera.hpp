#pragma once
// A camera hands out the newest frame it has, with the time it was captured. The frame's pixels
// belong to the backend and stay valid until the next grab on the same thread.
#include <cstdint>

#include "ringlet/hal/time.hpp"

namespace ringlet::hal {

enum class PixelFormat : std::uint8_t { kYuyv, kBgr8, kGray8 };

struct FrameView {
  Nanos capture_time{0};
  std::uint64_t sequence = 0;  // increases by one per captured frame; gaps mean dropped frames
  PixelFormat format = PixelFormat::kYuyv;
  int width = 0;
  int height = 0;
  int stride = 0;  // bytes per row
  const std::uint8_t* data = nullptr;
};

class Camera {
 public:
  virtual ~Camera() = default;
  /// Fills `out` with the newest frame. Returns false when no frame has been captured yet.
  virtual bool grab_latest(FrameView& out) noexcept = 0;
};

}  // namespace ringlet::hal
