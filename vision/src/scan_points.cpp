// Scan lines → line candidates. One small state machine per scan line (vertical or horizontal)
// consumes the sampled class grid; vertical lines are advanced together row by row so the class
// image is read sequentially. Checks that need geometry (the expected width of a 5 cm line there)
// and the frame's luminance run once per run, never per pixel.
#include <algorithm>
#include <cmath>
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

double dist(const hal::RobotPoint& a, const hal::RobotPoint& b) noexcept {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return std::sqrt(dx * dx + dy * dy);  // not hypot: no overflow possible here, and it is cheaper
}

// A green-white-green run [a, b] was found: check its edges and width, then keep its centre.
void emit(const Context& ctx, const ScanLine& line, int a, int b) noexcept {
  ++ctx.stats.runs;
  const int s = ctx.step;
  const int before = std::max(a - ctx.params.edge_offset * s, line.begin);
  const int after = std::min(b + ctx.params.edge_offset * s, line.last);
  const int mid = a + (b - a) / (2 * s) * s;
  const int y_in = luma_at(ctx.frame, line.x(mid), line.y(mid));
  const int rise = y_in - luma_at(ctx.frame, line.x(before), line.y(before));
  const int fall = y_in - luma_at(ctx.frame, line.x(after), line.y(after));
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
  ctx.out.push({line.pixel(centre), *g, static_cast<float>(extent), line.direction});
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
