// HOG descriptor of a fixed window (hog.hpp has the definition and why it follows OpenCV's).
#include "ringlet/vision/hog.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ringlet::vision {
namespace {

// The gradients of one window row (dx, dy as floats: exact small integers) into each pixel's two
// nearest orientation bins and its magnitude's share of each. Written as one straight loop of
// arithmetic and selects, no data-dependent branch and no call, so the compiler turns it into
// SIMD (this file is built with the vectoriser; vision/CMakeLists.txt): every lane does the same
// IEEE operations in the same order as a scalar pass would, so the bits are the same on every
// target. On a textured window the old per-pixel octant branches were mispredicted about half
// the time.
//
// The unsigned orientation θ ∈ [0, π] (OpenCV's cartToPolar modulo π; 0 for a zero gradient):
// (dx, dy) turned into the upper half plane, the octant's ratio t ∈ [0, 1], an odd degree-11
// polynomial fitted by least squares on Chebyshev nodes to atan on [0, 1] (|error| < 2e-6 rad,
// finer than OpenCV's own fast atan), then the octant's offset and sign. Bin centres are at
// (k + ½)·π/bins; a gradient splits between the two nearest, wrapping at 0 and π.
void orient_row(const float* gx, const float* gy, int n, int bins, float* mag_lower, float* mag_upper,
                std::int32_t* bin_lower, std::int32_t* bin_upper) noexcept {
  constexpr float kPi = std::numbers::pi_v<float>;
  const float bin_scale = static_cast<float>(bins) / kPi;
  for (int x = 0; x < n; ++x) {
    const bool down = gy[x] < 0.0f;  // the same orientation turned by π
    const float fx = down ? -gx[x] : gx[x];
    const float fy = down ? -gy[x] : gy[x];
    const bool left = fx < 0.0f;
    const float ax = left ? -fx : fx;
    const bool steep = fy > ax;
    const float num = steep ? ax : fy;
    const float den = steep ? fy : ax;
    const float t = num / (den == 0.0f ? 1.0f : den);
    const float t2 = t * t;
    const float a = t * (0.999979831616014f +
                         t2 * (-0.3326554200144419f +
                               t2 * (0.19366989156838635f +
                                     t2 * (-0.1166499864559437f + t2 * (0.05282220267342674f + t2 * -0.011769976944151949f)))));
    // θ = offset + sign · atan(t) by octant: flat and right 0 + a, flat and left π − a, steep and
    // right π/2 − a, steep and left π/2 + a.
    const float offset = steep ? 0.5f * kPi : (left ? kPi : 0.0f);
    const float theta = offset + (steep != left ? -a : a);
    const float mag = std::sqrt(fx * fx + fy * fy);
    const float position = theta * bin_scale - 0.5f;  // ≥ −0.5
    const int truncated = static_cast<int>(position);
    const int lower = truncated - (position < static_cast<float>(truncated) ? 1 : 0);  // floor
    const float share = position - static_cast<float>(lower);
    const int wrapped = lower < 0 ? lower + bins : (lower > bins - 1 ? bins - 1 : lower);
    mag_lower[x] = mag * (1.0f - share);
    mag_upper[x] = mag * share;
    bin_lower[x] = wrapped;
    bin_upper[x] = wrapped + 1 < bins ? wrapped + 1 : 0;
  }
}

}  // namespace

std::string HogParams::check() const {
  if (cell < 2 || cell > 64) return "cell size " + std::to_string(cell) + " px out of range [2, 64]";
  if (bins < 2 || bins > 64) return "bin count " + std::to_string(bins) + " out of range [2, 64]";
  if (block < 1 || block > 8) return "block size " + std::to_string(block) + " cells out of range [1, 8]";
  if (block_stride < 1 || block_stride > block) {
    return "block stride " + std::to_string(block_stride) + " cells out of range [1, " + std::to_string(block) + "]";
  }
  if (window_width < cell || window_height < cell || window_width > 256 || window_height > 256 ||
      window_width % cell != 0 || window_height % cell != 0) {
    return "window " + std::to_string(window_width) + "x" + std::to_string(window_height) +
           " px is not a whole number of " + std::to_string(cell) + " px cells within 256x256";
  }
  if (cells_x() < block || cells_y() < block) return "block larger than the window";
  if ((cells_x() - block) % block_stride != 0 || (cells_y() - block) % block_stride != 0) {
    return "blocks do not tile the window with stride " + std::to_string(block_stride);
  }
  return {};
}

HogExtractor::HogExtractor(const HogParams& params) : params_(params) {
  const int side = params_.block * params_.cell;
  axis_votes_.resize(static_cast<std::size_t>(side));
  // OpenCV's default window sigma: (block width + block height) / 8, here in px; the Gaussian is
  // centred at the block's middle, measured from pixel indices (not centres), as OpenCV does. It
  // is the product of one factor per axis.
  const double sigma = static_cast<double>(2 * side) / 8.0;
  for (int k = 0; k < side; ++k) {
    AxisVote& v = axis_votes_[static_cast<std::size_t>(k)];
    const double d = static_cast<double>(k) - static_cast<double>(side) * 0.5;
    const double gauss = std::exp(-d * d / (2.0 * sigma * sigma));
    // Position in cell units, cell centres at integers: vote into the two nearest cells that lie
    // inside the block, weighted by closeness.
    const double c = (static_cast<double>(k) + 0.5) / static_cast<double>(params_.cell) - 0.5;
    const int c0 = static_cast<int>(std::floor(c));
    const double f = c - static_cast<double>(c0);
    for (int a = 0; a < 2; ++a) {
      const int cell = c0 + a;
      const bool inside = cell >= 0 && cell < params_.block;
      v.cell[a] = inside ? cell : -1;
      v.weight[a] = inside ? static_cast<float>(gauss * (a == 0 ? 1.0 - f : f)) : 0.0f;
    }
  }
  const auto n = static_cast<std::size_t>(params_.window_width) * static_cast<std::size_t>(params_.window_height);
  for (int b = 0; b < 2; ++b) {
    magnitude_[b].assign(n, 0.0f);
    bin_[b].assign(n, 0);
    grad_[b].assign(static_cast<std::size_t>(params_.window_width), 0.0f);
  }
  row_hist_.assign(static_cast<std::size_t>(params_.window_height * params_.block * params_.bins), 0.0f);
}

bool HogExtractor::compute(std::span<const std::uint8_t> patch, std::span<float> out) noexcept {
  const int w = params_.window_width;
  const int h = params_.window_height;
  if (patch.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h) || out.size() != feature_length()) {
    return false;
  }
  const int bins = params_.bins;
  // Gradients; the neighbour beyond the border is the reflected one (x = −1 → 1), so the gradient
  // across the border is 0.
  float* gx = grad_[0].data();
  float* gy = grad_[1].data();
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* row = patch.data() + static_cast<std::size_t>(y * w);
    const std::uint8_t* above = patch.data() + static_cast<std::size_t>((y == 0 ? 1 : y - 1) * w);
    const std::uint8_t* below = patch.data() + static_cast<std::size_t>((y == h - 1 ? h - 2 : y + 1) * w);
    gx[0] = 0.0f;
    gx[w - 1] = 0.0f;
    for (int x = 1; x < w - 1; ++x) gx[x] = static_cast<float>(int{row[x + 1]} - int{row[x - 1]});
    for (int x = 0; x < w; ++x) gy[x] = static_cast<float>(int{below[x]} - int{above[x]});
    const auto i = static_cast<std::size_t>(y * w);
    orient_row(gx, gy, w, bins, magnitude_[0].data() + i, magnitude_[1].data() + i, bin_[0].data() + i,
               bin_[1].data() + i);
  }

  const int side = params_.block * params_.cell;
  const auto len = static_cast<std::size_t>(params_.block_length());
  const auto row_len = static_cast<std::size_t>(params_.block * bins);  // one row's cell columns × bins
  float* dst = out.data();
  for (int bx = 0; bx < params_.blocks_x(); ++bx) {
    // Each window row's votes into this block column's cell columns, the column factor applied.
    const int x0 = bx * params_.block_stride * params_.cell;
    for (int y = 0; y < h; ++y) {
      float* r = row_hist_.data() + static_cast<std::size_t>(y) * row_len;
      std::fill(r, r + row_len, 0.0f);
      for (int j = 0; j < side; ++j) {
        const auto p = static_cast<std::size_t>(y * w + x0 + j);
        const AxisVote& v = axis_votes_[static_cast<std::size_t>(j)];
        const float m0 = magnitude_[0][p];
        const float m1 = magnitude_[1][p];
        const auto b0 = static_cast<std::size_t>(bin_[0][p]);
        const auto b1 = static_cast<std::size_t>(bin_[1][p]);
        for (int a = 0; a < 2; ++a) {
          if (v.cell[a] < 0) continue;
          float* c = r + static_cast<std::size_t>(v.cell[a] * bins);
          c[b0] += m0 * v.weight[a];
          c[b1] += m1 * v.weight[a];
        }
      }
    }
    for (int by = 0; by < params_.blocks_y(); ++by) {
      // The block's rows into its cells (column by column), the row factor applied.
      float* hist = dst;
      std::fill(hist, hist + len, 0.0f);
      const int y0 = by * params_.block_stride * params_.cell;
      for (int i = 0; i < side; ++i) {
        const AxisVote& v = axis_votes_[static_cast<std::size_t>(i)];
        const float* r = row_hist_.data() + static_cast<std::size_t>(y0 + i) * row_len;
        for (int a = 0; a < 2; ++a) {
          if (v.cell[a] < 0) continue;
          for (int cx = 0; cx < params_.block; ++cx) {
            float* c = hist + static_cast<std::size_t>((cx * params_.block + v.cell[a]) * bins);
            const float* from = r + static_cast<std::size_t>(cx * bins);
            for (int b = 0; b < bins; ++b) c[b] += v.weight[a] * from[b];
          }
        }
      }
      // L2-Hys.
      float sum = 0.0f;
      for (std::size_t k = 0; k < len; ++k) sum += hist[k] * hist[k];
      float scale = 1.0f / (std::sqrt(sum) + static_cast<float>(len) * 0.1f);
      sum = 0.0f;
      for (std::size_t k = 0; k < len; ++k) {
        hist[k] = std::min(hist[k] * scale, 0.2f);
        sum += hist[k] * hist[k];
      }
      scale = 1.0f / (std::sqrt(sum) + 1e-3f);
      for (std::size_t k = 0; k < len; ++k) hist[k] *= scale;
      dst += len;
    }
  }
  return true;
}

}  // namespace ringlet::vision
