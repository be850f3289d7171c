#pragma once
// The project's PRNG: splitmix64 (Steele, Lea, Flood 2014). Tiny, fast, the same sequence on every
// target, seeded per frame so a frame's result depends on (seed, frame number) only.
#include <cstdint>

namespace ringlet::hal {

class SplitMix64 {
 public:
  explicit constexpr SplitMix64(std::uint64_t seed) noexcept : state_(seed) {}
  /// The generator for frame `frame` of a run seeded with `seed`.
  [[nodiscard]] static constexpr SplitMix64 for_frame(std::uint64_t seed, std::uint64_t frame) noexcept {
    SplitMix64 g(seed ^ (frame * 0xD1B54A32D192ED03ULL));
    (void)g.next();  // decorrelate neighbouring frames
    return g;
  }
  constexpr std::uint64_t next() noexcept {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  /// Uniform-ish in [0, n) (modulo bias < n / 2^64: irrelevant for point and sample counts); n > 0.
  constexpr std::uint64_t below(std::uint64_t n) noexcept { return next() % n; }

 private:
  std::uint64_t state_;
};

}  // namespace ringlet::hal
