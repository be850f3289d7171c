#pragma once
// One random SPL look per seed: the light (fluorescent, daylight, backlight), the camera's
// exposure and white balance, the carpet's shade, the sun patches, sensor noise, motion blur and
// a JPEG quality. ringlet-dataset draws every frame's look here and the colour-statistics test
// measures the same draws, so what the test proves about the ranges holds for the datasets.
// Pure integer arithmetic on a SplitMix64 stream (no <random> distributions): the same seed
// gives the same look on every target.
#include <cstdint>

#include "ringlet/sim_hal/camera_look.hpp"
#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal {

struct LookDraw {
  CameraLook look{};
  Lighting lighting{};   // the world's lighting with the drawn texture and sun patches
  int jpeg_quality = 0;  // 0: no JPEG round trip; else the quality (ringlet-dataset applies it)
};

/// Uniform doubles from SplitMix64, for the randomizers.
class SplitMix {
 public:
  explicit SplitMix(std::uint64_t seed) noexcept : state_(seed) {}
  std::uint64_t next() noexcept {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) noexcept {
    return lo + (hi - lo) * (static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0));
  }

 private:
  std::uint64_t state_;
};

/// The look of one frame, from `seed`, with the ball as given. `base` supplies the brightness.
[[nodiscard]] LookDraw draw_spl_look(const Lighting& base, BallLook ball, std::uint64_t seed) noexcept;

}  // namespace ringlet::sim_hal
