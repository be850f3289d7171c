// Scan lines → line candidates. One small state machine walks any scan line (vertical or
// horizontal) over the sampled grid of the class image; the checks that need geometry (the
// expected width of a 5 cm line there) run only once per run, never per pixel.
#include <algorithm>
#include <cmath>
#include <limits>

#include "ringlet/vision/scan_points.hpp"

namespace ringlet::vision {
namespace {

struct Context {
  const ClassImage& classes;
  const hal::FrameView& frame;
  const hal::CameraIntrinsics& k;
  const hal::CameraPose& pose;
  const ScanParams& params;
  CandidateBuffer& out;
  ScanStats& stats;
};

// One scan line: positions begin, begin + step, ... < end along the scan axis, at a fixed
// coordinate across it.
struct ScanLine {
  ScanDirection direction;
  int fixed;  // the column (vertical) or row (horizontal)
  int begin;
  int end;
  int step;
  std::span<const int> first_row;

  [[nodiscard]] int x(int p) const noexcept { return direction == ScanDirection::kVertical ? fixed : p; }
  [[nodiscard]] int y(int p) const noexcept { return direction == ScanDirection::kVertical ? p : fixed; }
  [[nodiscard]] ColourClass cls(const ClassImage& c, int p) const noexcept {
    // Horizontal scans cross columns whose horizon lies below this row: no ground there.
    if (direction == ScanDirection::kHorizontal && fixed < first_row[static_cast<std::size_t>(p)]) return ColourClass::kOther;
    return c.at(x(p), y(p));
  }
  [[nodiscard]] hal::Pixel pixel(double along) const noexcept {
    const double across = static_cast<double>(fixed) + 0.5;
    return direction == ScanDirection::kVertical ? hal::Pixel{across, along} : hal::Pixel{along, across};
  }
};

double dist(const hal::RobotPoint& a, const hal::RobotPoint& b) noexcept { return std::hypot(a.x - b.x, a.y - b.y); }

void emit(const Context& ctx, const ScanLine& line, int a, int b) noexcept {
  ++ctx.stats.runs;
  const int s = line.step;
  const int last = line.begin + (line.end - 1 - line.begin) / s * s;
  const int before = std::max(a - ctx.params.edge_offset * s, line.begin);
  const int after = std::min(b + ctx.params.edge_offset * s, last);
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
  const auto g = hal::pixel_to_ground(ctx.k, ctx.pose, line.pixel(centre));
  const auto g0 = hal::pixel_to_ground(ctx.k, ctx.pose, line.pixel(centre - 0.5));
  const auto g1 = hal::pixel_to_ground(ctx.k, ctx.pose, line.pixel(centre + 0.5));
  if (!g || !g0 || !g1) {
    ++ctx.stats.rejected_width;
    return;
  }
  // A line crossing the scan at right angles on the ground is line_width_m wide; at other angles
  // it is wider (1/sin), which the factor allows up to ~20°; shallower crossings are left to the
  // scans in the other direction.
  const double metres_per_px = std::max(dist(*g0, *g1), 1e-9);
  const double expected = ctx.params.line_width_m / metres_per_px;
  const double slack = ctx.params.width_slack_px + static_cast<double>(s);
  if (extent > ctx.params.max_width_factor * expected + slack || extent < ctx.params.min_width_factor * expected - slack) {
    ++ctx.stats.rejected_width;
    return;
  }
  ctx.out.push({line.pixel(centre), *g, static_cast<float>(extent), line.direction});
}

void scan(const Context& ctx, const ScanLine& line) noexcept {
  ++ctx.stats.scan_lines;
  const int s = line.step;
  const int gap_limit = (ctx.params.max_gap + 1) * s;
  constexpr int kNever = std::numeric_limits<int>::min() / 2;
  int last_field = kNever;
  bool in_run = false;
  bool pending = false;  // a white run that started next to green, waiting for green after it
  int run_a = 0;
  int run_b = 0;
  for (int p = line.begin; p < line.end; p += s) {
    const ColourClass c = line.cls(ctx.classes, p);
    if (c == ColourClass::kLine) {
      if (pending && p - run_b <= gap_limit) {
        in_run = true;  // a few misclassified pixels inside a line: the same run
        pending = false;
      } else if (!in_run) {
        pending = false;
        if (p - last_field > gap_limit) {
          run_a = kNever;  // no green just before: not a line on the field (until green again)
        } else {
          run_a = p;
        }
        in_run = true;
      }
      run_b = p;
      continue;
    }
    if (in_run) {
      in_run = false;
      pending = run_a != kNever;
    }
    if (c == ColourClass::kField) {
      if (pending && p - run_b <= gap_limit) emit(ctx, line, run_a, run_b);
      pending = false;
      last_field = p;
    } else if (pending && p - run_b > gap_limit) {
      pending = false;
    }
  }
}

}  // namespace

ScanStats scan_line_points(const ClassImage& classes, const hal::FrameView& frame, const hal::CameraIntrinsics& k,
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
  const Context ctx{classes, frame, k, pose, params, out, stats};
  // Vertical scan lines: each from its own column's horizon, aligned to the sampled grid.
  for (int x = 0; x < w; x += stride) {
    const int fr = std::max(first_row[static_cast<std::size_t>(x)], top);
    const int begin = top + (fr - top + s - 1) / s * s;
    scan(ctx, ScanLine{ScanDirection::kVertical, x, begin, h, s, first_row});
  }
  if (params.horizontal) {
    for (int y = top; y < h; y += stride) scan(ctx, ScanLine{ScanDirection::kHorizontal, y, 0, w, s, first_row});
  }
  return stats;
}

}  // namespace ringlet::vision
