// Scan lines → line candidates. One small state machine per scan line (vertical or horizontal)
// consumes the sampled class grid; vertical lines are advanced together row by row so the class
// image is read sequentially. Checks that need geometry (the expected width of a 5 cm line there)
// and the frame's luminance run once per run, never per pixel.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "ringlet/vision/scan_points.hpp"

namespace ringlet::vision {
namespace {

constexpr int kNever = std::numeric_limits<int>::min() / 2;
using RunState = LineScanner::RunState;

constexpr RunState kFresh{kNever, 0, 0, false, false};

struct Context {
  const hal::FrameView& frame;
  const hal::CameraIntrinsics& k;
  const hal::CameraPose& pose;
  const ScanParams& params;
  CandidateBuffer& out;
  ScanStats& stats;
  int step;
  int gap_limit;  // max distance from green to white and back (max_gap misclassified samples)
};

// Where a scan line lies: positions run along one axis at a fixed coordinate across it.
struct ScanLine {
  ScanDirection direction;
  int fixed;  // the column (vertical) or row (horizontal)
  int begin;  // first and last sampled position
  int last;

  [[nodiscard]] int x(int p) const noexcept { return direction == ScanDirection::kVertical ? fixed : p; }
  [[nodiscard]] int y(int p) const noexcept { return direction == ScanDirection::kVertical ? p : fixed; }
  [[nodiscard]] hal::Pixel pixel(double along) const noexcept {
    const double across = static_cast<double>(fixed) + 0.5;
    return direction == ScanDirection::kVertical ? hal::Pixel{across, along} : hal::Pixel{along, across};
  }
};

int saturation(const Yuv& p) noexcept { return std::abs(p.u - 128) + std::abs(p.v - 128); }

double dist(const hal::RobotPoint& a, const hal::RobotPoint& b) noexcept {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return std::sqrt(dx * dx + dy * dy);  // not hypot: no overflow possible here, and it is cheaper
}

// The structure tensor: sums of the Sobel gradient's products.
struct Tensor {
  double xx = 0.0, yy = 0.0, xy = 0.0;
};

template <std::uint8_t (*Luma)(const std::uint8_t*, int)>
void add_sobel(const std::uint8_t* up, const std::uint8_t* mid, const std::uint8_t* down, int x0, int x, int x1,
               Tensor& t) noexcept {
  const int gx = (Luma(up, x1) + 2 * Luma(mid, x1) + Luma(down, x1)) - (Luma(up, x0) + 2 * Luma(mid, x0) + Luma(down, x0));
  const int gy = (Luma(down, x0) + 2 * Luma(down, x) + Luma(down, x1)) - (Luma(up, x0) + 2 * Luma(up, x) + Luma(up, x1));
  t.xx += static_cast<double>(gx * gx);
  t.yy += static_cast<double>(gy * gy);
  t.xy += static_cast<double>(gx * gy);
}

// Sobel at (x, y), its neighbours clamped into the picture; the pixel format is read once.
void add_gradient(const hal::FrameView& f, int x, int y, Tensor& t) noexcept {
  const auto row = [&](int r) {
    return f.data + static_cast<std::size_t>(std::clamp(r, 0, f.height - 1)) * static_cast<std::size_t>(f.stride);
  };
  const std::uint8_t* up = row(y - 1);
  const std::uint8_t* mid = row(y);
  const std::uint8_t* down = row(y + 1);
  const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, f.width - 1);
  switch (f.format) {
    case hal::PixelFormat::kYuyv: add_sobel<yuyv_luma>(up, mid, down, x0, x, x1, t); break;
    case hal::PixelFormat::kBgr8: add_sobel<bgr_luma>(up, mid, down, x0, x, x1, t); break;
    case hal::PixelFormat::kGray8: add_sobel<gray_luma>(up, mid, down, x0, x, x1, t); break;
  }
}

// The paint's direction in the picture at the run's centre: the image gradients across the run's
// two edges agree on one orientation, across the paint; the paint runs at right angles to it.
// Each edge lies within a class step before the run's first sample (after its last): the Sobels
// at the sample and the half step outside it cover it. Where the paint meets another line, a
// robot's foot or noise the gradients disagree: no direction. Bounded: 2 (step / 2 + 1) Sobels
// and one back-projection per run. Kept out of line: inlined, it bloats the scan's row loop
// (BM_ScanPoints/2/1 400 us against 362 us).
struct PaintDirection {
  hal::RobotPoint along{};
  hal::RobotPoint across{};
};

[[gnu::noinline]] PaintDirection paint_direction(const Context& ctx, const ScanLine& line, int a, int b, double centre,
                               const hal::RobotPoint& ground, const hal::RobotPoint& next) noexcept {
  Tensor t;
  const int half = std::max(ctx.step / 2, 1);
  for (int p = a - half; p <= a; ++p) add_gradient(ctx.frame, line.x(p), line.y(p), t);
  for (int p = b; p <= b + half; ++p) add_gradient(ctx.frame, line.x(p), line.y(p), t);
  const double trace = t.xx + t.yy;
  const double spread = std::sqrt((t.xx - t.yy) * (t.xx - t.yy) + 4.0 * t.xy * t.xy);
  if (trace <= 0.0 || spread < ctx.params.min_coherence * trace) return {};
  // The dominant gradient's direction (gu, gv) from its doubled angle's cosine and sine by the
  // half-angle formulas: square roots only, which round the same on every target (libm's
  // atan2, sin and cos need not); the paint runs along (-gv, gu).
  const double c2 = (t.xx - t.yy) / spread;
  const double gu = std::sqrt(std::max(0.0, (1.0 + c2) / 2.0));
  const double gv = std::copysign(std::sqrt(std::max(0.0, (1.0 - c2) / 2.0)), t.xy);
  // The ground vectors of one pixel along the scan (`next`, which the width check projected) and
  // one across it span the ground vectors of every picture direction there (to first order).
  const hal::Pixel at = line.pixel(centre);
  const bool vertical = line.direction == ScanDirection::kVertical;
  const auto side = hal::pixel_to_ground(ctx.k, ctx.pose, vertical ? hal::Pixel{at.u + 1.0, at.v} : hal::Pixel{at.u, at.v + 1.0});
  if (!side) return {};
  // In picture coordinates (u, v): one pixel along u, one along v.
  const hal::RobotPoint du = vertical ? hal::RobotPoint{side->x - ground.x, side->y - ground.y}
                                      : hal::RobotPoint{next.x - ground.x, next.y - ground.y};
  const hal::RobotPoint dv = vertical ? hal::RobotPoint{next.x - ground.x, next.y - ground.y}
                                      : hal::RobotPoint{side->x - ground.x, side->y - ground.y};
  const auto ground_of = [&](double u, double v) { return hal::RobotPoint{u * du.x + v * dv.x, u * du.y + v * dv.y}; };
  return {ground_of(-gv, gu), ground_of(gu, gv)};
}

// A green-white-green run [a, b] was found: check its edges and width, then keep its centre.
void emit(const Context& ctx, const ScanLine& line, int a, int b) noexcept {
  ++ctx.stats.runs;
  const int s = ctx.step;
  const int before = std::max(a - ctx.params.edge_offset * s, line.begin);
  const int after = std::min(b + ctx.params.edge_offset * s, line.last);
  const int mid = a + (b - a) / (2 * s) * s;
  // The step into the paint and out of it: luminance, plus the saturation the carpet loses there.
  const Yuv in = yuv_at(ctx.frame, line.x(mid), line.y(mid));
  const auto step_from = [&](int p) {
    const Yuv o = yuv_at(ctx.frame, line.x(p), line.y(p));
    const int paler = saturation(o) - saturation(in);
    return in.y - o.y + (paler > 0 ? static_cast<int>(ctx.params.edge_chroma_weight * paler) : 0);
  };
  const int rise = step_from(before);
  const int fall = step_from(after);
  if (rise < ctx.params.edge_threshold || fall < ctx.params.edge_threshold) {
    ++ctx.stats.rejected_edge;
    return;
  }
  const double centre = (static_cast<double>(a) + static_cast<double>(b)) / 2.0 + 0.5;
  const double extent = static_cast<double>(b - a + s);
  // The ground footprint of one pixel along the scan, from the centre and its next pixel.
  const auto g = hal::pixel_to_ground(ctx.k, ctx.pose, line.pixel(centre));
  const auto g1 = hal::pixel_to_ground(ctx.k, ctx.pose, line.pixel(centre + 1.0));
  if (!g || !g1) {
    ++ctx.stats.rejected_width;
    return;
  }
  // A line crossing the scan at right angles on the ground is line_width_m wide; at other angles
  // it is wider (1/sin), which the factor allows down to ~20°; shallower crossings are left to the
  // scans in the other direction.
  const double metres_per_px = std::max(dist(*g, *g1), 1e-9);
  const double expected = ctx.params.line_width_m / metres_per_px;
  const double slack = ctx.params.width_slack_px + static_cast<double>(s);
  if (extent > ctx.params.max_width_factor * expected + slack || extent < ctx.params.min_width_factor * expected - slack) {
    ++ctx.stats.rejected_width;
    return;
  }
  const PaintDirection d = paint_direction(ctx, line, a, b, centre, *g, *g1);
  ctx.out.push({line.pixel(centre), *g, static_cast<float>(extent), line.direction, d.along, d.across});
}

// One sample at position p of class c. Returns true when a run [a, b] completed (green after it).
inline bool advance(RunState& st, int p, ColourClass c, int gap_limit, int& a, int& b) noexcept {
  if (c == ColourClass::kLine) {
    if (st.pending && p - st.run_b <= gap_limit) {
      st.in_run = true;  // a few misclassified pixels inside a line: the same run
      st.pending = false;
    } else if (!st.in_run) {
      st.pending = false;
      st.run_a = p - st.last_field > gap_limit ? kNever : p;  // kNever: no green just before
      st.in_run = true;
    }
    st.run_b = p;
    return false;
  }
  if (st.in_run) {
    st.in_run = false;
    st.pending = st.run_a != kNever;
  }
  bool done = false;
  if (c == ColourClass::kField) {
    if (st.pending && p - st.run_b <= gap_limit) {
      a = st.run_a;
      b = st.run_b;
      done = true;
    }
    st.pending = false;
    st.last_field = p;
  } else if (st.pending && p - st.run_b > gap_limit) {
    st.pending = false;
  }
  return done;
}

// Fast path shared by both directions: a green sample with nothing open only moves last_field.
inline bool step_sample(RunState& st, int p, ColourClass c, int gap_limit, int& a, int& b) noexcept {
  if (c == ColourClass::kField && !st.in_run && !st.pending) {
    st.last_field = p;
    return false;
  }
  return advance(st, p, c, gap_limit, a, b);
}

}  // namespace

ScanStats LineScanner::scan(const ClassImage& classes, const hal::FrameView& frame, const hal::CameraIntrinsics& k,
                            const hal::CameraPose& pose, std::span<const int> first_row, const ScanParams& params,
                            CandidateBuffer& out) noexcept {
  out.clear();
  ScanStats stats;
  const int w = classes.width();
  const int h = classes.height();
  if (frame.width != w || frame.height != h || first_row.size() < static_cast<std::size_t>(w)) return stats;
  const int s = classes.step();
  const int stride = std::max(s, (std::max(params.stride, 1) + s - 1) / s * s);
  const int top = classes.first_row();
  const Context ctx{frame, k, pose, params, out, stats, s, (params.max_gap + 1) * s};
  const int last_row = top + (std::max(h - 1 - top, 0)) / s * s;
  const int last_col = (w - 1) / s * s;
  const auto aligned = [&](int row) { return top + (std::max(row, top) - top + s - 1) / s * s; };

  // Vertical scan lines, all advanced together row by row; each starts at its own column's
  // horizon (aligned to the sampled grid).
  const auto columns = std::min(static_cast<std::size_t>((w + stride - 1) / stride), states_.size());
  std::fill(states_.begin(), states_.begin() + static_cast<std::ptrdiff_t>(columns), kFresh);
  int lowest_start = top;
  for (std::size_t i = 0; i < columns; ++i) {
    lowest_start = std::max(lowest_start, aligned(first_row[i * static_cast<std::size_t>(stride)]));
  }
  stats.scan_lines = static_cast<int>(columns);
  const int max_first_row = *std::max_element(first_row.begin(), first_row.begin() + w);
  for (int y = top; y < h; y += s) {
    const std::uint8_t* row = classes.row(y);
    const bool check_start = y < lowest_start;  // some columns may not have reached their ground yet
    for (std::size_t i = 0; i < columns; ++i) {
      const int x = static_cast<int>(i) * stride;
      if (check_start && y < aligned(first_row[static_cast<std::size_t>(x)])) continue;
      int a = 0, b = 0;
      if (step_sample(states_[i], y, static_cast<ColourClass>(row[x]), ctx.gap_limit, a, b)) {
        const int begin = aligned(first_row[static_cast<std::size_t>(x)]);
        emit(ctx, ScanLine{ScanDirection::kVertical, x, begin, last_row}, a, b);
      }
    }
  }

  if (params.horizontal) {
    for (int y = top; y < h; y += stride) {
      ++stats.scan_lines;
      const std::uint8_t* row = classes.row(y);
      const ScanLine line{ScanDirection::kHorizontal, y, 0, last_col};
      const bool check_ground = y < max_first_row;
      RunState st = kFresh;
      for (int x = 0; x < w; x += s) {
        if (!check_ground && !st.in_run && !st.pending && row[x] == static_cast<std::uint8_t>(ColourClass::kField)) {
          // Tight skip over plain green (most of the row): only where it ends matters.
          while (x + s < w && row[x + s] == static_cast<std::uint8_t>(ColourClass::kField)) x += s;
          st.last_field = x;
          continue;
        }
        // Columns whose horizon lies below this row have no ground here.
        const auto c = check_ground && y < first_row[static_cast<std::size_t>(x)] ? ColourClass::kOther
                                                                                   : static_cast<ColourClass>(row[x]);
        int a = 0, b = 0;
        if (step_sample(st, x, c, ctx.gap_limit, a, b)) emit(ctx, line, a, b);
      }
    }
  }
  return stats;
}

}  // namespace ringlet::vision
