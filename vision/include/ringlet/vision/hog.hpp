#pragma once
// Histograms of oriented gradients (Dalal & Triggs 2005) on a small luminance window, with the
// definition of OpenCV's cv::HOGDescriptor (so a test can hold one against the other):
//   - gradient [-1, 0, 1] in x and y; at the window's border the missing neighbour is the
//     reflected one (BORDER_REFLECT_101), so the gradient across the border is 0;
//   - unsigned orientation in [0°, 180°), `bins` bins centred at (k + ½)·180°/bins, each
//     gradient's magnitude split linearly between the two nearest bins (wrapping);
//   - cells of cell×cell px, blocks of block×block cells moved by `block_stride` cells; inside a
//     block each pixel votes into the (up to four) nearest cells with bilinear weights, times a
//     Gaussian of σ = (block width + block height in px) / 8 centred on the block;
//   - L2-Hys per block: v / (‖v‖ + 0.1·len), clip at 0.2, v / (‖v‖ + 1e-3);
//   - order: blocks column by column (x outer, y inner); inside a block cells column by column;
//     inside a cell the bins.
// The only known difference: OpenCV's orientation comes from its fast polynomial atan (~0.01°),
// ours from another polynomial (< 2e-6 rad, basic arithmetic only: the same bits on every target);
// tests/vision/hog_opencv_test.cpp measures the effect.
//
// Everything is sized at construction; compute() allocates nothing.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace ringlet::vision {

struct HogParams {
  int window_width = 32;   // px
  int window_height = 32;  // px
  int cell = 8;            // px per cell side
  int block = 2;           // cells per block side
  int block_stride = 1;    // cells between blocks
  int bins = 9;            // unsigned orientations over 180°

  [[nodiscard]] int cells_x() const noexcept { return window_width / cell; }
  [[nodiscard]] int cells_y() const noexcept { return window_height / cell; }
  [[nodiscard]] int blocks_x() const noexcept { return (cells_x() - block) / block_stride + 1; }
  [[nodiscard]] int blocks_y() const noexcept { return (cells_y() - block) / block_stride + 1; }
  [[nodiscard]] int block_length() const noexcept { return block * block * bins; }
  /// Floats in a descriptor.
  [[nodiscard]] int feature_length() const noexcept { return blocks_x() * blocks_y() * block_length(); }
  /// "" or what is wrong (window not a whole number of cells, block larger than the window, ...).
  [[nodiscard]] std::string check() const;

  /// The ball's window: 32×32 px, 324 features.
  [[nodiscard]] static HogParams ball() noexcept { return {}; }
  /// A standing NAO's window: 32×64 px (width × height), 756 features.
  [[nodiscard]] static HogParams robot() noexcept { return {32, 64, 8, 2, 1, 9}; }

  friend bool operator==(const HogParams&, const HogParams&) = default;
};

class HogExtractor {
 public:
  /// Precomputes the per-pixel cell and Gaussian weights. `params` must pass check().
  explicit HogExtractor(const HogParams& params);

  [[nodiscard]] const HogParams& params() const noexcept { return params_; }
  [[nodiscard]] std::size_t feature_length() const noexcept { return static_cast<std::size_t>(params_.feature_length()); }

  /// The descriptor of a window_width × window_height 8-bit patch (row-major, no padding) into
  /// `out` (feature_length() floats). Returns false (and writes nothing) on a size mismatch.
  bool compute(std::span<const std::uint8_t> patch, std::span<float> out) noexcept;

 private:
  // The block weight of a pixel (bilinear cell weight × Gaussian) is a product of a column and a
  // row factor, so a block's cell histograms are built in two passes: each window row's votes
  // into the cell columns of a block column (`row_hist_`, shared by the vertically overlapping
  // blocks), then those rows weighted into the cells. A tenth of the scattered adds of voting
  // every pixel into every block it lies in.
  struct AxisVote {  // one block-relative pixel column (or row): the ≤ 2 nearest cells' weights
    int cell[2];     // cell column (or row) inside the block, −1: no vote
    float weight[2];  // linear cell weight × the Gaussian's factor along this axis
  };
  HogParams params_;
  std::vector<AxisVote> axis_votes_;           // block side (px) entries; the same along x and y
  std::vector<float> magnitude_[2];            // per window pixel: magnitude share of the lower and the upper bin
  std::vector<std::int32_t> bin_[2];           // per window pixel: lower and upper bin
  std::vector<float> grad_[2];                 // one row's dx and dy
  std::vector<float> row_hist_;                // window rows × block cells along x × bins
};

}  // namespace ringlet::vision
