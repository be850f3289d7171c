#pragma once
// A fixed-bucket log-linear histogram of durations (HdrHistogram's idea): exact below 64 ns,
// 32 buckets per octave above, so any percentile is within ~3 % of the truth. Recording is a
// shift and an increment: no allocation, bounded time, fine inside the cycle.
#include <array>
#include <cstdint>

#include "ringlet/hal/time.hpp"

namespace ringlet::executive {

class DurationHistogram {
 public:
  static constexpr int kSubBits = 5;
  static constexpr int kSub = 1 << kSubBits;  // 32
  static constexpr int kMaxBit = 40;          // 2^40 ns ~ 18 min: anything longer lands in the top bucket
  static constexpr std::size_t kBuckets = static_cast<std::size_t>((kMaxBit - kSubBits + 1) * kSub);

  void record(hal::Nanos d) noexcept;
  void clear() noexcept;

  [[nodiscard]] std::uint64_t count() const noexcept { return count_; }
  [[nodiscard]] hal::Nanos min() const noexcept { return hal::Nanos{count_ ? min_ : 0}; }
  [[nodiscard]] hal::Nanos max() const noexcept { return hal::Nanos{max_}; }
  [[nodiscard]] hal::Nanos mean() const noexcept;
  /// The value below which a fraction `q` (0..1) of the recordings lie, as the upper edge of the
  /// bucket holding that rank, clamped to [min, max]. 0 when empty.
  [[nodiscard]] hal::Nanos percentile(double q) const noexcept;

  [[nodiscard]] static std::size_t bucket_of(std::uint64_t ns) noexcept;
  [[nodiscard]] static std::uint64_t bucket_lower(std::size_t bucket) noexcept;
  [[nodiscard]] static std::uint64_t bucket_upper(std::size_t bucket) noexcept;  // exclusive

 private:
  std::array<std::uint64_t, kBuckets> counts_{};
  std::uint64_t count_ = 0;
  std::int64_t min_ = 0;
  std::int64_t max_ = 0;
  std::uint64_t sum_ = 0;  // ns; overflows after 584 years of recorded time
};

}  // namespace ringlet::executive
