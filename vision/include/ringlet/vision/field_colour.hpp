#pragma once
// Colour that adapts to the frame: the field's colour is estimated from the image itself, and
// field, line and ball are classified relative to it instead of against fixed YUV boxes.
//
// Estimate (FieldColourEstimator::update, every frame, fixed buffers, bounded cost): a sparse grid
// of pixels below the horizon (every `sample_stride` px) fills a coarse 2-D chroma histogram
// (32 × 32 bins of 8 codes); the fullest green-ish bin's neighbourhood is the field's chroma cluster. Its
// members give the field's U, V and Y medians and spreads; the samples of field chroma (the
// classifier's rule) give per image cell (an 8 × 8 grid) the local field luminance (median). A cluster holding fewer than `min_field_fraction` of the samples, or
// whose chroma is not green-ish, is no field (a wall, the sky, a robot filling the view): the
// previous estimate is kept for up to `hold_frames` frames, then the pipeline falls back to the
// static colour table. Frame to frame the estimate is smoothed (exponential, `smoothing`/256 of
// the new value) and reset when it jumps (exposure or white balance changed at once).
//
// Classification (AdaptiveClassifier, built per frame from the estimate): a chroma table over
// 64 × 64 (U, V) bins says per bin "field chroma", "unsaturated" (line-able) and "ball chroma";
// a per-cell luminance table says "not too dark for field", "bright enough for a line" (the local
// field luminance plus a margin) and "in the ball's band"; a 64-entry table combines the two
// (ball first, then line, then field, else other). Rebuilding costs ~4096 + 64 × 256 entries.
#include <array>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>

#include "ringlet/hal/camera.hpp"
#include "ringlet/vision/colour.hpp"
#include "ringlet/vision/colour_table.hpp"

namespace ringlet::vision {

/// Which classifier the pipeline uses.
enum class ColourMode : std::uint8_t {
  kAdaptive,  // field colour from the frame; the static table only when no field is found
  kTable,     // the static colour table (thresholds, --lut, calibration) always
};

[[nodiscard]] constexpr const char* to_string(ColourMode m) noexcept {
  return m == ColourMode::kAdaptive ? "adaptive" : "table";
}

struct AdaptiveColourParams {
  // Estimation.
  int sample_stride = 12;             // px between samples in both directions (more if the grid
                                      // would exceed kMaxColourSamples)
  int min_samples = 64;               // fewer samples below the horizon: no estimate
  double min_field_fraction = 0.30;   // the field's chroma must hold this share of the samples
  int cluster_radius = 12;            // chroma codes (L∞) around the histogram peak giving the medians
  int field_max_u = 126;              // a field is green-ish: U and V not above these ...
  int field_max_v = 134;
  int field_min_chroma = 12;          // ... and (128 − U) + (128 − V) at least this (grey is no field,
                                      // nor an olive-grey floor: 8 let one with (116, 130) pass)
  int smoothing = 128;                // /256: weight of this frame's estimate against the previous
  int reset_jump_y = 24;              // a change of field Y (or U/V) larger than this resets the
  int reset_jump_uv = 10;             // smoothed estimate to this frame's
  int hold_frames = 30;               // frames a previous estimate is used when none is found
  int min_cell_samples = 3;           // field samples a cell needs for its own luminance (and for lines):
                                      //   far lines lie in cells mostly beyond the carpet (8: F1 −0.017)
  // Classification (relative to the estimate).
  // Field chroma: within a box of ±tolerance around the field's (U, V), where tolerance =
  // clamp(k·spread, min, max), or in the cone from neutral through it: projection t onto the
  // field's chroma in [cone_t_min, cone_t_max] (shade and sun scale chroma with brightness) and
  // distance from that ray ≤ tolerance + cone_slope·t·|field chroma|.
  int chroma_tolerance_min = 8;
  int chroma_tolerance_max = 12;
  double chroma_tolerance_k = 2.0;
  double cone_t_min = 0.35;
  double cone_t_max = 3.0;           // sunlit carpet: 2.8 × the shade's chroma seen (2.5 left it "other")
  double cone_slope = 0.2;
  // Shade scales chroma with brightness (t ≈ Y / field Y). Field chroma paler than pale_t of the
  // field's (grey with a tint: a ball's white, a robot's shell, bluish white balance) is field only
  // where the pixel is darker than pale_y_ratio × the field's Y in light (the brighter of the cell's
  // carpet and the frame's field), i.e. where it could be shade.
  double pale_t = 0.6;
  double pale_y_ratio = 0.85;
  int field_y_below = 80;             // field: Y ≥ local field Y − max(this, k·spread) (no upper
  double field_y_k = 3.0;             // bound: bright, saturated carpet is sunlit field, not line)
  int line_margin = 28;               // line: Y ≥ local field Y + max(line_margin, k·spread, ratio·Y)
  double line_margin_k = 3.0;
  double line_margin_ratio = 0.25;
  double line_headroom = 0.5;         // ... but at most this share of (255 − local field Y), and at
                                      // least line_margin: bright carpet leaves clipped paint little room
  int line_y_max = 245;               // ... and never above this (nor at the carpet's Y or below it): on
                                      // carpet near white (sun, overexposure) paint clipped at 250–255
                                      // is told from it by its chroma alone
  int line_max_chroma = 36;           // line: |U − 128| and |V − 128| within this (unsaturated; real
                                      // bluish-white lines have U down to 95)
  YuvRange ball{40, 235, 0, 118, 158, 255};  // the orange ball option: an absolute box (ColourThresholds)
};

inline constexpr int kMaxColourSamples = 8192;

/// Where this frame's colour classes came from.
enum class ColourSource : std::uint8_t {
  kTable,     // the static table (kTable mode, or no field estimate)
  kFrame,     // the field estimated from this frame
  kPrevious,  // no field in this frame: a recent frame's estimate
};

[[nodiscard]] constexpr const char* to_string(ColourSource s) noexcept {
  switch (s) {
    case ColourSource::kTable: return "table";
    case ColourSource::kFrame: return "frame";
    case ColourSource::kPrevious: return "previous";
  }
  return "?";
}

inline constexpr int kColourCellsX = 8;
inline constexpr int kColourCellsY = 8;
inline constexpr int kColourCells = kColourCellsX * kColourCellsY;

/// The field's colour as estimated (and smoothed), with how sure the estimator is.
struct FieldColourEstimate {
  bool valid = false;          // a field colour is known (this frame's or a held one)
  ColourSource source = ColourSource::kTable;
  std::uint8_t y = 0, u = 128, v = 128;   // field medians (smoothed)
  std::uint8_t y_spread = 0;   // half the inter-quartile range of the field's Y
  std::uint8_t uv_spread = 0;  // half the larger inter-quartile range of its U and V
  double confidence = 0.0;     // share of the samples in the field cluster (0 when none), × hold decay
  int samples = 0;             // pixels sampled below the horizon this frame
  int field_samples = 0;       // of them in the field cluster
  int age = 0;                 // frames since the estimate was last measured (0: this frame)
  bool reset = false;          // this frame's estimate jumped: smoothing restarted
  std::array<std::uint8_t, kColourCells> cell_y{};  // local field Y per image cell (row-major)
  std::uint64_t field_cells = 0;  // bit c: cell c holds field (min_cell_samples); lines only near field
};

class FieldColourEstimator {
 public:
  explicit FieldColourEstimator(const AdaptiveColourParams& params = {}) noexcept : params_(params) {}

  /// Samples `frame` below `first_row` (per column; may be shorter than the width, the rest
  /// counts as sky) and updates the estimate. Allocates nothing.
  const FieldColourEstimate& update(const hal::FrameView& frame, std::span<const int> first_row) noexcept;
  /// This frame's measurement only, no smoothing or holding (calibration, tests).
  [[nodiscard]] static FieldColourEstimate measure(const hal::FrameView& frame, std::span<const int> first_row,
                                                   const AdaptiveColourParams& params);

  [[nodiscard]] const FieldColourEstimate& estimate() const noexcept { return smoothed_; }
  void forget() noexcept { smoothed_ = {}; }
  [[nodiscard]] const AdaptiveColourParams& params() const noexcept { return params_; }

 private:
  struct Sample {
    Yuv yuv;
    std::uint8_t cell;
  };
  FieldColourEstimate measure_frame(const hal::FrameView& frame, std::span<const int> first_row) noexcept;

  AdaptiveColourParams params_;
  FieldColourEstimate smoothed_;
  // Scratch, kept here so that a frame allocates nothing and the stack stays small.
  std::array<Sample, kMaxColourSamples> samples_{};
  std::array<std::uint16_t, 32 * 32> chroma_hist_{};
  std::array<std::uint32_t, 32 * 32> sum_u_{}, sum_v_{};
  std::array<std::array<std::uint16_t, 64>, kColourCells> cell_hist_{};
};

/// The field-chroma rule (box or cone, AdaptiveColourParams) in integers, for one estimate.
struct FieldChromaRule {
  int fu = 128, fv = 128;   // field chroma
  int fx = 0, fy = 0;       // field chroma − neutral
  long f2 = 0;              // |f|²
  int tolerance = 0;        // box half-width
  long t_min256 = 0, t_max256 = 0, slope256 = 0, tol_f256 = 0, pale_t256 = 0;
  long pale_ratio256 = 0;   // pale_y_ratio · 256
  int line_max_chroma = 0;

  FieldChromaRule() = default;
  FieldChromaRule(const FieldColourEstimate& e, const AdaptiveColourParams& p) noexcept;
  [[nodiscard]] bool field(int u, int v) const noexcept {
    if (std::abs(u - fu) <= tolerance && std::abs(v - fv) <= tolerance) return true;
    if (f2 == 0) return false;
    const long cx = u - 128, cy = v - 128;
    const long dot = cx * fx + cy * fy;
    const long cross = std::labs(cx * fy - cy * fx);
    return dot * 256 >= t_min256 * f2 && dot * 256 <= t_max256 * f2 && cross * 256 <= tol_f256 + slope256 * dot;
  }
  /// Field chroma, but paler than pale_t of the field's (shade, or a tinted grey).
  [[nodiscard]] bool pale(int u, int v) const noexcept {
    const long dot = static_cast<long>(u - 128) * fx + static_cast<long>(v - 128) * fy;
    return dot * 256 < pale_t256 * f2 && field(u, v);
  }
  /// Pale field chroma counts as field only where Y · 256 ≤ this (darker than pale_y_ratio × field_y).
  [[nodiscard]] long pale_y256(int field_y) const noexcept { return pale_ratio256 * field_y; }
  [[nodiscard]] bool unsaturated(int u, int v) const noexcept {
    return std::abs(u - 128) <= line_max_chroma && std::abs(v - 128) <= line_max_chroma;
  }
};

/// The per-frame thresholds and small tables derived from an estimate.
class AdaptiveClassifier {
 public:
  static constexpr int kChromaBits = 6;  // 64 × 64 (U, V) bins

  explicit AdaptiveClassifier(const AdaptiveColourParams& params = {}) noexcept : params_(params) {}

  /// Rebuilds the tables for `estimate` (valid) and an image of `width` × `height`.
  void build(const FieldColourEstimate& estimate, int width, int height) noexcept;

  /// The rule itself, exactly as the tables apply it up to the chroma bins' quantisation
  /// (the chroma tests use the bin's centre).
  [[nodiscard]] ColourClass classify(std::uint8_t y, std::uint8_t u, std::uint8_t v, int cell) const noexcept {
    return static_cast<ColourClass>(combine_[static_cast<std::size_t>(chroma_[chroma_index(u, v)] << kBits | luma_[cell_offset(cell) + y])]);
  }
  /// Cell (row-major in the 8 × 8 grid) of pixel (x, y).
  [[nodiscard]] int cell_of(int x, int y) const noexcept {
    return (y * kColourCellsY / height_) * kColourCellsX + x * kColourCellsX / width_;
  }
  [[nodiscard]] static std::size_t chroma_index(std::uint8_t u, std::uint8_t v) noexcept {
    return static_cast<std::size_t>(u >> (8 - kChromaBits)) << kChromaBits | static_cast<std::size_t>(v >> (8 - kChromaBits));
  }
  [[nodiscard]] static std::size_t cell_offset(int cell) noexcept { return static_cast<std::size_t>(cell) * 256U; }

  [[nodiscard]] const std::uint8_t* chroma_table() const noexcept { return chroma_.data(); }
  [[nodiscard]] const std::uint8_t* luma_table(int cell) const noexcept { return luma_.data() + cell_offset(cell); }
  [[nodiscard]] const std::uint8_t* combine_table() const noexcept { return combine_.data(); }
  [[nodiscard]] int width() const noexcept { return width_; }
  [[nodiscard]] int height() const noexcept { return height_; }
  /// The line threshold (Y) of a cell, for reports and tests.
  [[nodiscard]] int line_y_min(int cell) const noexcept { return line_y_[static_cast<std::size_t>(cell)]; }
  /// The same rule by plain comparisons on exact (Y, U, V), without the tables (the benchmark
  /// measures both ways; the tables won, see vision/README.md).
  [[nodiscard]] ColourClass classify_by_comparison(std::uint8_t y, std::uint8_t u, std::uint8_t v, int cell) const noexcept {
    const auto c = static_cast<std::size_t>(cell);
    if (params_.ball.contains({y, u, v})) return ColourClass::kBall;
    if (y >= line_y_[c] && rule_.unsaturated(u, v)) return ColourClass::kLine;
    if (y >= field_lo_[c] && rule_.field(u, v) && (y * 256L <= pale_y256_[c] || !rule_.pale(u, v))) return ColourClass::kField;
    return ColourClass::kOther;
  }

  // Bits of the chroma and luminance tables; a class is the combination table's entry at
  // chroma bits << kBits | luminance bits. Pale: the chroma is pale field chroma / the pixel is
  // dark enough for that to be shade.
  static constexpr std::uint8_t kFieldBit = 1, kLineBit = 2, kBallBit = 4, kPaleBit = 8;
  static constexpr int kBits = 4;

 private:
  AdaptiveColourParams params_;
  int width_ = 1;
  int height_ = 1;
  std::array<std::uint8_t, 1U << (2 * kChromaBits)> chroma_{};
  std::array<std::uint8_t, kColourCells * 256> luma_{};
  std::array<std::uint8_t, 1U << (2 * kBits)> combine_{};
  std::array<int, kColourCells> line_y_{};
  std::array<int, kColourCells> field_lo_{};
  std::array<long, kColourCells> pale_y256_{};  // pale field chroma is field at Y·256 ≤ this
  FieldChromaRule rule_;
};

}  // namespace ringlet::vision
