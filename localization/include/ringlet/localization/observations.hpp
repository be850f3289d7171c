#pragma once
// What vision saw of the field in one camera frame, in the robot frame at the frame's capture
// (x ahead, y left, m: hal::RobotPoint): ground line segments and the centre circle's centre.
#include <array>
#include <cstddef>
#include <cstdint>

namespace ringlet::localization {

struct LineObservation {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
};

struct Observations {
  static constexpr std::size_t kMaxLines = 12;  // as wb::FieldLines carries
  std::array<LineObservation, kMaxLines> lines{};
  std::size_t line_count = 0;
  bool circle_seen = false;
  double circle_x = 0.0;  // the circle's centre
  double circle_y = 0.0;
  std::int64_t capture_time_ns = 0;

  [[nodiscard]] bool empty() const noexcept { return line_count == 0 && !circle_seen; }
  /// Appends a segment; false (and nothing changes) when full.
  bool add_line(const LineObservation& l) noexcept {
    if (line_count == kMaxLines) return false;
    lines[line_count++] = l;
    return true;
  }
};

}  // namespace ringlet::localization
