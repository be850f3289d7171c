// DurationHistogram: bucket layout, exact statistics, and percentile accuracy against the exact
// percentile of random data.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "ringlet/executive/histogram.hpp"

namespace ringlet::executive {
namespace {

using H = DurationHistogram;
using hal::Nanos;
using namespace std::chrono_literals;

// The exact q-quantile with the histogram's rank definition: the smallest rank r >= q * n.
std::int64_t exact_percentile(const std::vector<std::int64_t>& sorted, double q) {
  const auto n = static_cast<double>(sorted.size());
  const auto rank = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(q * n)));
  return sorted[rank - 1];
}

TEST(Histogram, EmptyIsAllZero) {
  const H h;
  EXPECT_EQ(h.count(), 0U);
  EXPECT_EQ(h.min(), hal::Nanos{0});
  EXPECT_EQ(h.max(), hal::Nanos{0});
  EXPECT_EQ(h.mean(), hal::Nanos{0});
  EXPECT_EQ(h.percentile(0.5), hal::Nanos{0});
  EXPECT_EQ(h.percentile(1.0), hal::Nanos{0});
}

TEST(Histogram, ExactRegionBelow64ns) {
  for (std::uint64_t v = 0; v < 64; ++v) {
    const auto b = H::bucket_of(v);
    EXPECT_EQ(b, static_cast<std::size_t>(v));
    EXPECT_EQ(H::bucket_lower(b), v);
    EXPECT_EQ(H::bucket_upper(b), v + 1);
  }
  H h;
  for (std::int64_t v = 0; v < 64; ++v) h.record(hal::Nanos{v});
  EXPECT_EQ(h.count(), 64U);
  // With one recording per value, the q-quantile is exact: rank ceil(q*64) holds value rank-1.
  for (int r = 1; r <= 64; ++r) {
    const double q = r / 64.0;
    EXPECT_EQ(h.percentile(q), hal::Nanos{r - 1}) << "q=" << q;
  }
}

TEST(Histogram, BucketsAreContiguousMonotonicAndFine) {
  for (std::size_t b = 0; b < H::kBuckets; ++b) {
    const auto lo = H::bucket_lower(b);
    const auto hi = H::bucket_upper(b);
    ASSERT_LT(lo, hi) << "bucket " << b;
    if (b + 1 < H::kBuckets) {
      ASSERT_EQ(hi, H::bucket_lower(b + 1)) << "gap or overlap after bucket " << b;
    }
    ASSERT_EQ(H::bucket_of(lo), b) << "lower edge of bucket " << b;
    ASSERT_EQ(H::bucket_of(hi - 1), b) << "upper edge of bucket " << b;
    if (b >= 64) {
      // 32 sub-buckets per octave: width / lower edge <= 1/32.
      ASSERT_LE((hi - lo) * 32, lo) << "bucket " << b;
    }
  }
  EXPECT_EQ(H::bucket_lower(0), 0U);
  EXPECT_EQ(H::bucket_upper(H::kBuckets - 1), std::uint64_t{1} << H::kMaxBit);
}

TEST(Histogram, HugeValuesLandInTheLastBucket) {
  const std::uint64_t top = std::uint64_t{1} << H::kMaxBit;
  EXPECT_EQ(H::bucket_of(top - 1), H::kBuckets - 1);
  EXPECT_EQ(H::bucket_of(top), H::kBuckets - 1);
  EXPECT_EQ(H::bucket_of(top * 1000), H::kBuckets - 1);
  EXPECT_EQ(H::bucket_of(std::numeric_limits<std::uint64_t>::max()), H::kBuckets - 1);

  H h;
  const hal::Nanos hour = std::chrono::hours{1};
  h.record(1ms);
  h.record(hour);
  EXPECT_EQ(h.max(), hour);  // max stays exact
  // The top bucket has no upper edge: a percentile landing in it is the (exact) maximum, not
  // 2^40 ns, which would under-report a long stall.
  EXPECT_EQ(h.percentile(1.0), hour);
  EXPECT_EQ(h.percentile(0.9), hour);
  EXPECT_GE(h.percentile(0.5), 1ms);  // the upper edge of 1 ms's bucket: within 1/32
  EXPECT_LE(h.percentile(0.5), Nanos{1ms} + Nanos{1ms} / 32);
  h.record(hal::Nanos{std::numeric_limits<std::int64_t>::max()});
  EXPECT_EQ(h.count(), 3U);
  EXPECT_EQ(h.max().count(), std::numeric_limits<std::int64_t>::max());
}

TEST(Histogram, MinMaxMeanExact) {
  H h;
  h.record(3003ns);
  h.record(1000ns);
  h.record(2000ns);
  EXPECT_EQ(h.min(), 1000ns);
  EXPECT_EQ(h.max(), 3003ns);
  EXPECT_EQ(h.mean(), 2001ns);

  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::int64_t> dist(1, 50'000'000);
  H r;
  std::int64_t lo = std::numeric_limits<std::int64_t>::max();
  std::int64_t hi = 0;
  std::uint64_t sum = 0;
  for (int i = 0; i < 10'000; ++i) {
    const auto v = dist(rng);
    r.record(hal::Nanos{v});
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    sum += static_cast<std::uint64_t>(v);
  }
  EXPECT_EQ(r.min().count(), lo);
  EXPECT_EQ(r.max().count(), hi);
  EXPECT_EQ(r.mean().count(), static_cast<std::int64_t>(sum / 10'000));
}

TEST(Histogram, NegativeDurationsCountAsZero) {
  H h;
  h.record(hal::Nanos{-5});
  h.record(10ns);
  EXPECT_EQ(h.count(), 2U);
  EXPECT_EQ(h.min(), 0ns);
  EXPECT_EQ(h.percentile(0.5), 0ns);
}

TEST(Histogram, PercentilesWithinBucketPrecisionOfTheExactValue) {
  std::mt19937_64 rng(20240611);
  // Log-uniform from 50 ns to 200 ms: exercises the exact region and many octaves.
  std::uniform_real_distribution<double> log_dist(std::log(50.0), std::log(2e8));
  std::vector<std::int64_t> values(100'000);
  H h;
  for (auto& v : values) {
    v = static_cast<std::int64_t>(std::exp(log_dist(rng)));
    h.record(hal::Nanos{v});
  }
  std::sort(values.begin(), values.end());
  for (const double q : {0.0, 0.0001, 0.01, 0.1, 0.25, 0.5, 0.75, 0.9, 0.99, 0.999, 0.9999, 1.0}) {
    const auto exact = static_cast<double>(exact_percentile(values, q));
    const auto got = static_cast<double>(h.percentile(q).count());
    EXPECT_LE(std::abs(got - exact), 0.032 * exact) << "q=" << q << " exact " << exact << " got " << got;
    EXPECT_GE(got, exact) << "q=" << q << ": the percentile is the bucket's upper edge";
  }
  EXPECT_EQ(h.percentile(0.0).count(), values.front());
  EXPECT_EQ(h.percentile(1.0).count(), values.back());
}

TEST(Histogram, PercentilesOfSkewedData) {
  // 99 % of samples at ~1 us, 1 % at ~5 ms: p99 must stay low, p99.9 must find the tail.
  std::mt19937_64 rng(99);
  std::normal_distribution<double> fast(1000.0, 50.0);
  std::normal_distribution<double> slow(5e6, 1e5);
  std::vector<std::int64_t> values;
  H h;
  for (int i = 0; i < 50'000; ++i) {
    const double x = (i % 100 == 99) ? slow(rng) : fast(rng);
    const auto v = static_cast<std::int64_t>(std::max(1.0, x));
    values.push_back(v);
    h.record(hal::Nanos{v});
  }
  std::sort(values.begin(), values.end());
  for (const double q : {0.5, 0.99, 0.995, 0.999}) {
    const auto exact = static_cast<double>(exact_percentile(values, q));
    const auto got = static_cast<double>(h.percentile(q).count());
    EXPECT_LE(std::abs(got - exact), 0.032 * exact) << "q=" << q;
  }
  EXPECT_LT(h.percentile(0.98), 2us);
  EXPECT_GT(h.percentile(0.999), 4ms);
}

TEST(Histogram, ClearForgetsEverything) {
  H h;
  h.record(5ms);
  h.record(7ms);
  h.clear();
  EXPECT_EQ(h.count(), 0U);
  EXPECT_EQ(h.max(), 0ns);
  EXPECT_EQ(h.percentile(0.5), 0ns);
  h.record(3us);
  EXPECT_EQ(h.min(), 3us);
  EXPECT_EQ(h.max(), 3us);
}

}  // namespace
}  // namespace ringlet::executive
