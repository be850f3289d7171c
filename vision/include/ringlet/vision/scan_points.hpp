#pragma once
// Line candidate points from scan lines: green → white → green runs along vertical scan lines
// every `stride` columns (and horizontal ones every `stride` rows, for lines seen end-on), below
// the horizon, checked by luminance edges and by the width a 5 cm line has at that distance.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

#include "ringlet/hal/camera.hpp"
#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/vision/class_image.hpp"

namespace ringlet::vision {

struct ScanParams {
  int stride = 2;                   // px between scan lines (rounded up to a multiple of the class step)
  bool horizontal = true;           // also scan rows (lines running down the image)
  int edge_threshold = 24;          // min step into and out of the run: the line's centre vs
                                    // `edge_offset` samples outside it, its rise in Y plus
  double edge_chroma_weight = 0.5;  //   this × the saturation (|U − 128| + |V − 128|) it has less:
                                    //   on sunlit carpet near white the paint differs mostly in
                                    //   chroma (val2_s101 frame 1385: carpet Y 230 U 50, paint
                                    //   Y 254 U 124; with Y alone no candidate on its 450 px)
  int edge_offset = 2;              // samples outside the run where the background is read
  int max_gap = 2;                  // samples of neither field nor line allowed between green and
                                    // white (blurred edges)
  double line_width_m = 0.05;       // painted line width
  double max_width_factor = 3.0;    // runs wider than this × expected are robots / white blobs
  double min_width_factor = 0.3;    // runs narrower than this × expected are noise
  double width_slack_px = 2.0;      // added to both bounds (+ the class step): edge pixels
  double min_coherence = 0.3;       // the run's edges give the line's direction when their
                                    // gradients agree this well (structure-tensor coherence)
};

enum class ScanDirection : std::uint8_t { kVertical, kHorizontal };

struct CandidatePoint {
  hal::Pixel pixel{};          // the run's centre (pixel-centre coordinates: pixel i spans [i, i+1))
  hal::RobotPoint ground{};    // where it lies on the ground, robot frame
  float width_px = 0.0F;       // the run's extent along the scan line
  ScanDirection direction = ScanDirection::kVertical;
  // The paint's direction in the picture there, from the run's edges, as the ground vectors one
  // pixel along it and one pixel across it span: a ground direction h = α·along + β·across runs
  // at atan(|β/α|) to the paint in the picture. Both {0, 0}: not known.
  hal::RobotPoint ground_along{};
  hal::RobotPoint ground_across{};
};

/// How a ground direction h runs against a candidate's paint in the picture: h = α·along + β·across
/// (CandidatePoint::ground_along, ground_across) runs at atan|β/α| = atan(off / on) to it, where
/// off = |along × h| and on = |h × across|.
struct PaintOffset {
  double off = 0.0, on = 0.0;
};
[[nodiscard]] inline PaintOffset paint_offset(const hal::RobotPoint& along, const hal::RobotPoint& across, double hx,
                                              double hy) noexcept {
  return {std::abs(along.x * hy - along.y * hx), std::abs(hx * across.y - hy * across.x)};
}
/// Whether the run's edges gave the paint's direction (ground_along is {0, 0} when not).
[[nodiscard]] inline bool knows_paint_direction(const hal::RobotPoint& along) noexcept {
  return along.x != 0.0 || along.y != 0.0;
}
/// A direction gate of `max_deg` degrees as paint_runs_along takes it: its tangent, or −1 (no
/// gate) when max_deg ≤ 0.
[[nodiscard]] inline double direction_gate_tan(double max_deg) noexcept {
  return max_deg > 0.0 ? std::tan(max_deg * std::numbers::pi / 180.0) : -1.0;
}
/// Whether the ground direction (hx, hy), of any length, runs within the gate `max_tan`
/// (direction_gate_tan) of a candidate's paint in the picture; true without a gate or where the
/// paint's direction is not known.
[[nodiscard]] inline bool paint_runs_along(const hal::RobotPoint& along, const hal::RobotPoint& across, double hx,
                                           double hy, double max_tan) noexcept {
  if (max_tan < 0.0 || !knows_paint_direction(along)) return true;
  const PaintOffset o = paint_offset(along, across, hx, hy);
  return o.off <= max_tan * o.on;
}

/// A fixed-capacity list of candidates: storage allocated at construction, push refuses (and
/// counts) points beyond the capacity.
class CandidateBuffer {
 public:
  explicit CandidateBuffer(std::size_t capacity) : points_(capacity) {}
  void clear() noexcept { count_ = 0; dropped_ = 0; }
  bool push(const CandidatePoint& p) noexcept {
    if (count_ == points_.size()) {
      ++dropped_;
      return false;
    }
    points_[count_++] = p;
    return true;
  }
  [[nodiscard]] std::span<const CandidatePoint> points() const noexcept { return {points_.data(), count_}; }
  [[nodiscard]] std::size_t size() const noexcept { return count_; }
  [[nodiscard]] std::size_t capacity() const noexcept { return points_.size(); }
  [[nodiscard]] std::size_t dropped() const noexcept { return dropped_; }

 private:
  std::vector<CandidatePoint> points_;
  std::size_t count_ = 0;
  std::size_t dropped_ = 0;
};

struct ScanStats {
  int scan_lines = 0;
  int runs = 0;             // green-white-green runs found
  int rejected_edge = 0;    // too little luminance step
  int rejected_width = 0;   // implausible width for a line at that distance (or no ground)
};

/// The scanner keeps one small run state per vertical scan line so that it can walk the class
/// image row by row (cache-friendly) instead of column by column; the states are allocated at
/// construction for frames up to `max_width` wide.
class LineScanner {
 public:
  struct RunState {
    int last_field;  // position of the last green sample
    int run_a;       // current / pending white run [run_a, run_b]; kNoGreen: not after green
    int run_b;
    bool in_run;
    bool pending;    // a white run that started next to green, waiting for green after it
  };

  explicit LineScanner(int max_width) : states_(static_cast<std::size_t>(max_width > 0 ? max_width : 0)) {}

  /// Fills `out` (cleared first) with the candidates of one frame. `first_row` per column as from
  /// horizon_rows(); the class image must have been classified from `frame`. Candidates come in
  /// row order (vertical scans, interleaved across columns), then the horizontal scans.
  ScanStats scan(const ClassImage& classes, const hal::FrameView& frame, const hal::CameraIntrinsics& k,
                 const hal::CameraPose& pose, std::span<const int> first_row, const ScanParams& params,
                 CandidateBuffer& out) noexcept;

 private:
  std::vector<RunState> states_;
};

}  // namespace ringlet::vision
