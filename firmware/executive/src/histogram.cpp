#include "ringlet/executive/histogram.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace ringlet::executive {

std::size_t DurationHistogram::bucket_of(std::uint64_t ns) noexcept {
  if (ns < 2 * kSub) return static_cast<std::size_t>(ns);  // exact region
  const int msb = static_cast<int>(std::bit_width(ns)) - 1;
  if (msb >= kMaxBit) return kBuckets - 1;
  const int shift = msb - kSubBits;
  // (ns >> shift) is in [kSub, 2 kSub): the kSubBits bits below the leading one pick the bucket.
  return static_cast<std::size_t>((shift + 1) * kSub) + static_cast<std::size_t>((ns >> shift) - kSub);
}

std::uint64_t DurationHistogram::bucket_lower(std::size_t bucket) noexcept {
  if (bucket < 2 * kSub) return bucket;
  const auto shift = bucket / kSub - 1;
  return (kSub + bucket % kSub) << shift;
}

std::uint64_t DurationHistogram::bucket_upper(std::size_t bucket) noexcept {
  if (bucket < 2 * kSub) return bucket + 1;
  const auto shift = bucket / kSub - 1;
  return (kSub + bucket % kSub + 1) << shift;
}

void DurationHistogram::record(hal::Nanos d) noexcept {
  const std::int64_t v = std::max<std::int64_t>(0, d.count());
  ++counts_[bucket_of(static_cast<std::uint64_t>(v))];
  if (count_ == 0 || v < min_) min_ = v;
  if (count_ == 0 || v > max_) max_ = v;
  ++count_;
  sum_ += static_cast<std::uint64_t>(v);
}

void DurationHistogram::clear() noexcept { *this = DurationHistogram{}; }

hal::Nanos DurationHistogram::mean() const noexcept {
  return hal::Nanos{count_ ? static_cast<std::int64_t>(sum_ / count_) : 0};
}

hal::Nanos DurationHistogram::percentile(double q) const noexcept {
  if (count_ == 0) return hal::Nanos{0};
  q = std::clamp(q, 0.0, 1.0);
  // The rank of the q-quantile, 1-based: the smallest rank r with r >= q * count.
  const auto rank = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(count_))));
  std::uint64_t seen = 0;
  for (std::size_t b = 0; b < kBuckets; ++b) {
    seen += counts_[b];
    if (seen >= rank) {
      // The top bucket also holds everything >= 2^kMaxBit: it has no upper edge but the maximum.
      if (b == kBuckets - 1) return hal::Nanos{max_};
      const auto upper = static_cast<std::int64_t>(bucket_upper(b)) - 1;
      return hal::Nanos{std::clamp(upper, min_, max_)};
    }
  }
  return hal::Nanos{max_};
}

}  // namespace ringlet::executive
