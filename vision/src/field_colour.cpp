// The field's colour from the frame itself (FieldColourEstimator) and the per-frame tables that
// classify relative to it (AdaptiveClassifier). See field_colour.hpp for the method.
#include "ringlet/vision/field_colour.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>

#include "ringlet/vision/class_image.hpp"  // yuv_at

namespace ringlet::vision {
namespace {

constexpr int kHistBits = 5;  // chroma histogram: 32 × 32 bins of 8 codes
constexpr int kHistBins = 1 << kHistBits;

// The bin below which num/den of a histogram's `total` lies.
template <std::size_t N>
int percentile(const std::array<std::uint16_t, N>& h, int total, int num, int den) noexcept {
  const long target = static_cast<long>(total) * num / den;
  long seen = 0;
  for (std::size_t i = 0; i < N; ++i) {
    seen += h[i];
    if (seen > target) return static_cast<int>(i);
  }
  return static_cast<int>(N) - 1;
}

// The least Y a line pixel needs over field of luminance `fy` (Y spread `spread`): the margin
// max(line_margin, k·spread, ratio·Y), but never more than line_headroom of the way to white (and
// at least line_margin): on bright or sunlit carpet 0.25·Y or 3·spread would leave the paint,
// clipped at 255, no room to pass.
int line_threshold(int fy, int spread, const AdaptiveColourParams& p) noexcept {
  const int margin = std::max({p.line_margin, static_cast<int>(std::lround(p.line_margin_k * spread)),
                               static_cast<int>(std::lround(p.line_margin_ratio * fy))});
  const int headroom = std::max(p.line_margin, static_cast<int>(std::lround(p.line_headroom * (255 - fy))));
  return std::max(std::min(fy + std::min(margin, headroom), p.line_y_max), fy + 1);
}

std::uint8_t clamp_byte(long x) noexcept { return static_cast<std::uint8_t>(std::clamp(x, 0L, 255L)); }

// s + w/256 · (m − s), rounded half away from zero: integer, so every host agrees.
std::uint8_t blend(std::uint8_t s, std::uint8_t m, int w) noexcept {
  const int d = static_cast<int>(m) - static_cast<int>(s);
  return clamp_byte(static_cast<long>(s) + (d * w + (d >= 0 ? 128 : -128)) / 256);
}

// Green-ish chroma: within the field limits (widened by slack) and at least field_min_chroma from
// neutral. One rule for the histogram's bins, the cluster's samples and the estimate itself.
bool green_ish(int u, int v, const AdaptiveColourParams& p, int slack = 0) noexcept {
  return u <= p.field_max_u + slack && v <= p.field_max_v + slack && (128 - u) + (128 - v) >= p.field_min_chroma;
}

}  // namespace

FieldChromaRule::FieldChromaRule(const FieldColourEstimate& e, const AdaptiveColourParams& p) noexcept
    : fu(e.u), fv(e.v), fx(e.u - 128), fy(e.v - 128), f2(static_cast<long>(fx) * fx + static_cast<long>(fy) * fy) {
  tolerance = std::clamp(static_cast<int>(std::lround(p.chroma_tolerance_k * e.uv_spread)), p.chroma_tolerance_min,
                         std::max(p.chroma_tolerance_min, p.chroma_tolerance_max));
  t_min256 = std::lround(p.cone_t_min * 256.0);
  t_max256 = std::lround(p.cone_t_max * 256.0);
  slope256 = std::lround(p.cone_slope * 256.0);
  tol_f256 = std::lround(tolerance * std::sqrt(static_cast<double>(f2)) * 256.0);
  pale_t256 = std::lround(p.pale_t * 256.0);
  pale_ratio256 = std::lround(p.pale_y_ratio * 256.0);
  line_max_chroma = p.line_max_chroma;
}

FieldColourEstimate FieldColourEstimator::measure(const hal::FrameView& frame, std::span<const int> first_row,
                                                  const AdaptiveColourParams& params) {
  // Off the cycle path (tools, tests): the scratch is too big for a stack frame.
  const auto estimator = std::make_unique<FieldColourEstimator>(params);
  return estimator->measure_frame(frame, first_row);
}

FieldColourEstimate FieldColourEstimator::measure_frame(const hal::FrameView& frame, std::span<const int> first_row) noexcept {
  FieldColourEstimate e;
  if (frame.data == nullptr || frame.width <= 0 || frame.height <= 0) return e;
  const AdaptiveColourParams& params = params_;

  // The sparse grid below the horizon, read once (a grid coarser than sample_stride when the
  // image is large, so at most kMaxColourSamples), with the coarse chroma histogram.
  int stride = std::max(params.sample_stride, 1);
  while (static_cast<long>(frame.width / stride + 1) * (frame.height / stride + 1) > kMaxColourSamples) ++stride;
  chroma_hist_.fill(0);
  sum_u_.fill(0);
  sum_v_.fill(0);
  int n = 0;
  const int columns = std::min(frame.width, static_cast<int>(first_row.size()));
  for (int y = stride / 2; y < frame.height; y += stride) {
    const int cell_row = (y * kColourCellsY / frame.height) * kColourCellsX;
    for (int x = stride / 2; x < columns; x += stride) {
      if (y < first_row[static_cast<std::size_t>(x)]) continue;
      const Yuv p = yuv_at(frame, x, y);
      const std::size_t b = static_cast<std::size_t>(p.u >> (8 - kHistBits)) << kHistBits | (p.v >> (8 - kHistBits));
      ++chroma_hist_[b];
      sum_u_[b] += p.u;
      sum_v_[b] += p.v;
      samples_[static_cast<std::size_t>(n++)] = {p, static_cast<std::uint8_t>(cell_row + x * kColourCellsX / frame.width)};
    }
  }
  e.samples = n;
  if (n < std::max(params.min_samples, 1)) return e;

  // The peak of the 3 × 3-smoothed histogram (a cluster straddling bin borders still wins).
  long best = -1;
  int best_u = 0, best_v = 0;
  const auto bin = [&](int u, int v) -> long {
    return u >= 0 && u < kHistBins && v >= 0 && v < kHistBins ? chroma_hist_[static_cast<std::size_t>(u * kHistBins + v)] : 0;
  };
  // Only green-ish bins can be the field's peak (with a bin's slack): a grey floor or wall around
  // the field may cover more of the view than the carpet does.
  constexpr int kBinWidth = 1 << (8 - kHistBits);
  const auto green_bin = [&](int bu, int bv) {
    return green_ish(bu * kBinWidth + kBinWidth / 2, bv * kBinWidth + kBinWidth / 2, params, kBinWidth / 2);
  };
  for (int bu = 0; bu < kHistBins; ++bu) {
    for (int bv = 0; bv < kHistBins; ++bv) {
      if (chroma_hist_[static_cast<std::size_t>(bu * kHistBins + bv)] == 0 || !green_bin(bu, bv)) continue;
      long s = 0;
      for (int du = -1; du <= 1; ++du)
        for (int dv = -1; dv <= 1; ++dv) s += green_bin(bu + du, bv + dv) ? bin(bu + du, bv + dv) : 0;
      if (s > best) {
        best = s;
        best_u = bu;
        best_v = bv;
      }
    }
  }
  std::uint64_t su = 0, sv = 0, m = 0;
  for (int du = -1; du <= 1; ++du)
    for (int dv = -1; dv <= 1; ++dv) {
      const int u = best_u + du, v = best_v + dv;
      if (u < 0 || u >= kHistBins || v < 0 || v >= kHistBins || !green_bin(u, v)) continue;
      const auto b = static_cast<std::size_t>(u * kHistBins + v);
      su += sum_u_[b];
      sv += sum_v_[b];
      m += chroma_hist_[b];
    }
  if (m == 0) return e;
  const int cu = static_cast<int>((su + m / 2) / m);
  const int cv = static_cast<int>((sv + m / 2) / m);

  // The cluster's members (green-ish chroma within cluster_radius of the centre: the grey of a
  // floor or of robots next to a dull carpet stays out): Y, U, V medians, spreads.
  const int r = std::max(params.cluster_radius, 1);
  std::array<std::uint16_t, 256> hy{}, hu{}, hv{};
  int members = 0;
  for (int i = 0; i < n; ++i) {
    const Yuv& p = samples_[static_cast<std::size_t>(i)].yuv;
    if (std::abs(p.u - cu) > r || std::abs(p.v - cv) > r || !green_ish(p.u, p.v, params)) continue;
    ++hy[p.y];
    ++hu[p.u];
    ++hv[p.v];
    ++members;
  }
  if (members == 0) return e;
  const int y25 = percentile(hy, members, 1, 4), y50 = percentile(hy, members, 1, 2), y75 = percentile(hy, members, 3, 4);
  const int u25 = percentile(hu, members, 1, 4), u50 = percentile(hu, members, 1, 2), u75 = percentile(hu, members, 3, 4);
  const int v25 = percentile(hv, members, 1, 4), v50 = percentile(hv, members, 1, 2), v75 = percentile(hv, members, 3, 4);
  e.y = clamp_byte(y50);
  e.u = clamp_byte(u50);
  e.v = clamp_byte(v50);
  e.y_spread = clamp_byte((y75 - y25 + 1) / 2);
  e.uv_spread = clamp_byte((std::max(u75 - u25, v75 - v25) + 1) / 2);
  const bool green = green_ish(e.u, e.v, params);

  // Every sample of field chroma (the classifier's rule: shaded and sunlit carpet too; pale field
  // chroma only where darker than the field) counts as field: its share is the confidence, and per
  // cell its median Y is the local field luminance.
  const FieldChromaRule rule(e, params);
  const long pale_y256 = rule.pale_y256(e.y);
  for (auto& h : cell_hist_) h.fill(0);
  std::array<int, kColourCells> cell_n{};
  int field = 0;
  const int paint_y = line_threshold(e.y, e.y_spread, params);
  std::array<int, kColourCells> cell_paint{};
  for (int i = 0; i < n; ++i) {
    const Sample& s = samples_[static_cast<std::size_t>(i)];
    if (!rule.field(s.yuv.u, s.yuv.v) || (s.yuv.y * 256L > pale_y256 && rule.pale(s.yuv.u, s.yuv.v))) continue;
    ++field;
    ++cell_n[s.cell];
    // Paint of the field's tint (cream lines in warm light): field chroma, but what the frame's
    // rule would call line must not become the cell's carpet luminance, or a near, wide line
    // filling much of its cell raises the cell's line threshold above itself.
    if (s.yuv.y >= paint_y && rule.unsaturated(s.yuv.u, s.yuv.v)) {
      ++cell_paint[s.cell];
      continue;
    }
    ++cell_hist_[s.cell][s.yuv.y >> 2];
  }
  e.field_samples = field;
  const double fraction = static_cast<double>(field) / static_cast<double>(n);
  if (fraction < params.min_field_fraction || !green) return e;
  for (std::size_t c = 0; c < e.cell_y.size(); ++c) {
    const bool field_here = cell_n[c] >= std::max(params.min_cell_samples, 1);
    const int carpet = cell_n[c] - cell_paint[c];
    e.cell_y[c] = field_here && carpet > 0
                      ? clamp_byte(percentile(cell_hist_[c], carpet, 1, 2) * 4 + 2)
                      : e.y;
    if (field_here) e.field_cells |= std::uint64_t{1} << c;
  }
  e.valid = true;
  e.source = ColourSource::kFrame;
  e.confidence = fraction;
  return e;
}

const FieldColourEstimate& FieldColourEstimator::update(const hal::FrameView& frame, std::span<const int> first_row) noexcept {
  const FieldColourEstimate m = measure_frame(frame, first_row);
  FieldColourEstimate& s = smoothed_;
  if (!m.valid) {
    if (s.valid && s.age < params_.hold_frames) {
      ++s.age;
      s.source = ColourSource::kPrevious;
      s.confidence *= static_cast<double>(params_.hold_frames - s.age) / static_cast<double>(std::max(params_.hold_frames, 1));
      s.samples = m.samples;
      s.field_samples = m.field_samples;
      s.reset = false;
    } else {
      s = m;  // invalid: the pipeline uses its static table
    }
    return s;
  }
  const bool jump = std::abs(m.y - s.y) > params_.reset_jump_y || std::abs(m.u - s.u) > params_.reset_jump_uv ||
                    std::abs(m.v - s.v) > params_.reset_jump_uv;
  if (!s.valid || jump) {
    const bool was_valid = s.valid;
    s = m;
    s.reset = was_valid;
    return s;
  }
  const int w = std::clamp(params_.smoothing, 1, 256);
  s.y = blend(s.y, m.y, w);
  s.u = blend(s.u, m.u, w);
  s.v = blend(s.v, m.v, w);
  s.y_spread = blend(s.y_spread, m.y_spread, w);
  s.uv_spread = blend(s.uv_spread, m.uv_spread, w);
  for (std::size_t c = 0; c < s.cell_y.size(); ++c) s.cell_y[c] = blend(s.cell_y[c], m.cell_y[c], w);
  s.field_cells = m.field_cells;
  s.source = ColourSource::kFrame;
  s.confidence = m.confidence;
  s.samples = m.samples;
  s.field_samples = m.field_samples;
  s.age = 0;
  s.reset = false;
  return s;
}

void AdaptiveClassifier::build(const FieldColourEstimate& e, int width, int height) noexcept {
  const AdaptiveColourParams& p = params_;
  width_ = std::max(width, 1);
  height_ = std::max(height, 1);
  rule_ = FieldChromaRule(e, p);
  constexpr int kBins = 1 << kChromaBits;
  constexpr int kShift = 8 - kChromaBits;
  for (int bu = 0; bu < kBins; ++bu) {
    for (int bv = 0; bv < kBins; ++bv) {
      const int u = (bu << kShift) + (1 << kShift) / 2;
      const int v = (bv << kShift) + (1 << kShift) / 2;
      std::uint8_t bits = 0;
      if (rule_.field(u, v)) bits |= rule_.pale(u, v) ? kPaleBit : kFieldBit;
      if (rule_.unsaturated(u, v)) bits |= kLineBit;
      if (u >= p.ball.u_min && u <= p.ball.u_max && v >= p.ball.v_min && v <= p.ball.v_max) bits |= kBallBit;
      chroma_[static_cast<std::size_t>(bu * kBins + bv)] = bits;
    }
  }
  const int spread_y = e.y_spread;
  for (int c = 0; c < kColourCells; ++c) {
    const int fy = e.cell_y[static_cast<std::size_t>(c)];
    // Lines only where there is field (a grey floor or wall beyond the carpet is bright and
    // unsaturated too); may exceed 255: no line in that cell.
    const int line_y = ((e.field_cells >> c) & 1U) != 0 ? line_threshold(fy, spread_y, p) : 256;
    const int field_lo = fy - std::max(p.field_y_below, static_cast<int>(std::lround(p.field_y_k * spread_y)));
    line_y_[static_cast<std::size_t>(c)] = line_y;
    field_lo_[static_cast<std::size_t>(c)] = field_lo;
    // Pale chroma is shade where darker than the field in light: the brighter of the cell's carpet
    // and the frame's. A cell wholly in shade has the shade's luminance as its carpet, and its
    // shade (at 0.55 of the sunlit chroma: val_s101 frame 1082) would be "other" against itself
    // (0.85 of it); the estimate judged its samples against the frame's field luminance too.
    const long pale_y256 = rule_.pale_y256(std::max(fy, static_cast<int>(e.y)));
    pale_y256_[static_cast<std::size_t>(c)] = pale_y256;
    std::uint8_t* luma = luma_.data() + cell_offset(c);
    for (int y = 0; y < 256; ++y) {
      std::uint8_t bits = 0;
      if (y >= field_lo) bits |= kFieldBit;  // brighter than a line but saturated: sunlit carpet
      if (y >= field_lo && y * 256L <= pale_y256) bits |= kPaleBit;
      if (y >= line_y) bits |= kLineBit;
      if (y >= p.ball.y_min && y <= p.ball.y_max) bits |= kBallBit;
      luma[y] = bits;
    }
  }
  for (std::size_t i = 0; i < combine_.size(); ++i) {
    constexpr std::size_t kMask = (1U << kBits) - 1U;
    const auto both = static_cast<std::uint8_t>((i >> kBits) & i & kMask);
    ColourClass c = ColourClass::kOther;
    if ((both & kBallBit) != 0) {
      c = ColourClass::kBall;
    } else if ((both & kLineBit) != 0) {
      c = ColourClass::kLine;
    } else if ((both & (kFieldBit | kPaleBit)) != 0) {
      c = ColourClass::kField;
    }
    combine_[i] = static_cast<std::uint8_t>(c);
  }
}

}  // namespace ringlet::vision
