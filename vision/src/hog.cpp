// HOG descriptor of a fixed window (hog.hpp has the definition and why it follows OpenCV's).
#include "ringlet/vision/hog.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ringlet::vision {
namespace {

// The gradient's direction in [0, 2π) (as OpenCV's cartToPolar; 0 for a zero gradient) from basic
// arithmetic only, so every target gives the same bits: octant reduction and an odd degree-11
// polynomial fitted by least squares on Chebyshev nodes to atan on [0, 1] (|error| < 2e-6 rad,
// finer than OpenCV's own fast atan). Cheaper than std::atan2, which dominated the descriptor.
double orientation(int dx, int dy) noexcept {
  if (dx == 0 && dy == 0) return 0.0;
  const double ax = dx < 0 ? -dx : dx;
  const double ay = dy < 0 ? -dy : dy;
  const bool steep = ay > ax;
  const double t = steep ? ax / ay : ay / ax;
  const double t2 = t * t;
  double a = t * (0.999979831616014 +
                  t2 * (-0.3326554200144419 +
                        t2 * (0.19366989156838635 +
                              t2 * (-0.1166499864559437 + t2 * (0.05282220267342674 + t2 * -0.011769976944151949)))));
  if (steep) a = 0.5 * std::numbers::pi - a;
  if (dx < 0) a = std::numbers::pi - a;
  if (dy < 0) a = 2.0 * std::numbers::pi - a;
  return a >= 2.0 * std::numbers::pi ? 0.0 : a;
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
  block_weights_.resize(static_cast<std::size_t>(side) * static_cast<std::size_t>(side));
  // OpenCV's default window sigma: (block width + block height) / 8, here in px; the Gaussian is
  // centred at the block's middle, measured from pixel indices (not centres), as OpenCV does.
  const float sigma = static_cast<float>(2 * side) / 8.0f;
  const float inv = 1.0f / (sigma * sigma * 2.0f);
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      PixelWeights& pw = block_weights_[static_cast<std::size_t>(i * side + j)];
      const float di = static_cast<float>(i) - static_cast<float>(side) * 0.5f;
      const float dj = static_cast<float>(j) - static_cast<float>(side) * 0.5f;
      const auto gauss = static_cast<float>(std::exp(static_cast<double>(-(di * di + dj * dj) * inv)));
      // Position in cell units, cell centres at integers: vote into the two nearest cells per
      // axis that lie inside the block, weighted by closeness.
      const float cx = (static_cast<float>(j) + 0.5f) / static_cast<float>(params_.cell) - 0.5f;
      const float cy = (static_cast<float>(i) + 0.5f) / static_cast<float>(params_.cell) - 0.5f;
      const int x0 = static_cast<int>(std::floor(cx));
      const int y0 = static_cast<int>(std::floor(cy));
      const float fx = cx - static_cast<float>(x0);
      const float fy = cy - static_cast<float>(y0);
      int k = 0;
      for (int dy = 0; dy < 2; ++dy) {
        for (int dx = 0; dx < 2; ++dx) {
          const int ccx = x0 + dx;
          const int ccy = y0 + dy;
          const float wx = dx == 0 ? 1.0f - fx : fx;
          const float wy = dy == 0 ? 1.0f - fy : fy;
          if (ccx < 0 || ccx >= params_.block || ccy < 0 || ccy >= params_.block) {
            pw.cell[k] = -1;
            pw.weight[k] = 0.0f;
          } else {
            pw.cell[k] = static_cast<std::int16_t>(ccx * params_.block + ccy);
            pw.weight[k] = gauss * (wx * wy);
          }
          ++k;
        }
      }
    }
  }
  const auto n = static_cast<std::size_t>(params_.window_width) * static_cast<std::size_t>(params_.window_height);
  for (int b = 0; b < 2; ++b) {
    magnitude_[b].assign(n, 0.0f);
    bin_[b].assign(n, 0);
  }
}

bool HogExtractor::compute(std::span<const std::uint8_t> patch, std::span<float> out) noexcept {
  const int w = params_.window_width;
  const int h = params_.window_height;
  if (patch.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h) || out.size() != feature_length()) {
    return false;
  }
  const int bins = params_.bins;
  const float angle_scale = static_cast<float>(bins) / std::numbers::pi_v<float>;
  // Gradients; the neighbour beyond the border is the reflected one (x = −1 → 1).
  for (int y = 0; y < h; ++y) {
    const int ym = y == 0 ? 1 : y - 1;
    const int yp = y == h - 1 ? h - 2 : y + 1;
    for (int x = 0; x < w; ++x) {
      const int xm = x == 0 ? 1 : x - 1;
      const int xp = x == w - 1 ? w - 2 : x + 1;
      const auto at = [&](int xx, int yy) { return static_cast<int>(patch[static_cast<std::size_t>(yy * w + xx)]); };
      const int dx = at(xp, y) - at(xm, y);
      const int dy = at(x, yp) - at(x, ym);
      const auto i = static_cast<std::size_t>(y * w + x);
      const auto fdx = static_cast<float>(dx);
      const auto fdy = static_cast<float>(dy);
      const float mag = std::sqrt(fdx * fdx + fdy * fdy);
      const double angle = orientation(dx, dy);
      float a = static_cast<float>(angle) * angle_scale - 0.5f;
      int lower = static_cast<int>(std::floor(a));
      a -= static_cast<float>(lower);
      if (lower < 0) {
        lower += bins;
      } else if (lower >= bins) {
        lower -= bins;
      }
      lower = std::clamp(lower, 0, bins - 1);
      const int upper = lower + 1 < bins ? lower + 1 : 0;
      magnitude_[0][i] = mag * (1.0f - a);
      magnitude_[1][i] = mag * a;
      bin_[0][i] = static_cast<std::uint8_t>(lower);
      bin_[1][i] = static_cast<std::uint8_t>(upper);
    }
  }

  const int side = params_.block * params_.cell;
  const auto len = static_cast<std::size_t>(params_.block_length());
  float* dst = out.data();
  for (int bx = 0; bx < params_.blocks_x(); ++bx) {
    for (int by = 0; by < params_.blocks_y(); ++by) {
      float* hist = dst;
      std::fill(hist, hist + len, 0.0f);
      const int x0 = bx * params_.block_stride * params_.cell;
      const int y0 = by * params_.block_stride * params_.cell;
      for (int i = 0; i < side; ++i) {
        for (int j = 0; j < side; ++j) {
          const auto p = static_cast<std::size_t>((y0 + i) * w + x0 + j);
          const PixelWeights& pw = block_weights_[static_cast<std::size_t>(i * side + j)];
          const float m0 = magnitude_[0][p];
          const float m1 = magnitude_[1][p];
          const std::size_t b0 = bin_[0][p];
          const std::size_t b1 = bin_[1][p];
          for (int k = 0; k < 4; ++k) {
            if (pw.cell[k] < 0) continue;
            float* c = hist + static_cast<std::size_t>(pw.cell[k]) * static_cast<std::size_t>(bins);
            c[b0] += m0 * pw.weight[k];
            c[b1] += m1 * pw.weight[k];
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
