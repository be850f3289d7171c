#pragma once
// Checks a fitted line piece against the classified picture before it is reported. A painted
// line is a band of line-class pixels with field on both sides, all along it. RANSAC works on
// candidate points only (green-white-green runs), and such runs also occur on robots' feet and
// legs, goal posts and the floor beyond the carpet: a hypothesis through a few of them and a few
// true line points can gather enough inliers, yet in the picture it crosses robots and plain
// green. So at `samples` points along the piece (on the ground, projected) the checker asks:
// is the class image "line" there (within the fit's slack), and is the first thing beside the
// band, on both sides, field (after at most a blurred edge)? The piece is kept when at least
// `min_share` of the samples inside the picture pass: a line half hidden by the ball or a robot
// still passes, a fit across robots does not.
//
// Cost: per sample two ground-to-image projections and a few dozen class-image reads, no
// allocation (~2 µs per piece on the development host at 24 samples).
#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/hal/geometry.hpp"
#include "ringlet/vision/class_image.hpp"

namespace ringlet::vision {

struct LineCheckParams {
  bool enabled = true;
  int samples = 24;               // points along the piece (its ends excluded)
  double min_share = 0.4;         // of the samples inside the picture that must look like a line
                                  // (0.5 refused far lines whose paint comes and goes: validation
                                  // F1 −0.002 to −0.004)
  int min_judged = 4;             // fewer samples inside the picture: the piece is not judged (kept)
  double line_width_m = 0.05;     // painted width: the band's expected width in the picture
  double centre_slack_px = 2.0;   // the fit may sit this far (plus half the band) off the paint
  double band_factor = 2.5;       // the band may look this many times its expected width (blur) ...
  double band_slack_px = 3.0;     // ... plus this
  int edge_px = 2;                // pixels of neither line nor field allowed between band and field
  // A band thinner than this (half width, px) is judged over a short stretch: a sample passes when
  // the band looks like paint at it or up to thin_reach_px along the line either way. Far lines
  // one or two pixels wide flicker between line and field classes (a camera's faint far paint) or
  // break into dashes (a renderer's aliasing), so the one pixel under a sample says little there.
  double thin_half_width_px = 1.5;
  int thin_reach_px = 4;
};

class LineCheck {
 public:
  LineCheck(const ClassImage& classes, const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
            const LineCheckParams& params) noexcept
      : classes_(classes), k_(k), pose_(pose), params_(params) {}

  /// Share of the judged samples along the ground segment [a, b] that look like a painted line
  /// (1 when fewer than min_judged samples fall inside the picture).
  [[nodiscard]] double share(const hal::RobotPoint& a, const hal::RobotPoint& b) const noexcept;
  [[nodiscard]] bool accepts(const hal::RobotPoint& a, const hal::RobotPoint& b) const noexcept {
    return judge_piece(a, b).accepted;
  }

  /// The part of [a, b] between its first and last samples that look like paint, as fractions of
  /// the way from a to b ({0, 1}: nothing to cut). Stray collinear points (a robot's white sole,
  /// the ball) can carry a fit past the painted line's end; the end samples show it.
  struct Span {
    double from = 0.0;
    double to = 1.0;
  };
  /// What the reporting needs of a piece, from one pass over its samples: accepts() and the
  /// painted span (when disabled: accepted, nothing to cut).
  struct Verdict {
    bool accepted = true;
    double share = 1.0;
    Span span{};
  };
  [[nodiscard]] Verdict judge_piece(const hal::RobotPoint& a, const hal::RobotPoint& b) const noexcept {
    return params_.enabled ? assess(a, b) : Verdict{};
  }
  /// Half the painted width in the picture at ground point `at` of a line with unit ground
  /// direction (dx, dy): the distance between `at` and a point half a width across, projected.
  /// 0 when either does not project.
  [[nodiscard]] double half_width_px(const hal::RobotPoint& at, double dx, double dy) const noexcept;
  [[nodiscard]] Span painted_span(const hal::RobotPoint& a, const hal::RobotPoint& b) const noexcept;

 private:
  // half_width_px with `at` already projected to `c` (judge() has it).
  [[nodiscard]] double half_width_from(const hal::Pixel& c, const hal::RobotPoint& at, double dx, double dy) const noexcept;
  // Share and painted span in one pass, whether or not the check is enabled.
  [[nodiscard]] Verdict assess(const hal::RobotPoint& a, const hal::RobotPoint& b) const noexcept;
  // Sample i of n along [a, b]: 1 looks like paint, 0 does not, -1 not judged (outside the picture).
  [[nodiscard]] int judge(const hal::RobotPoint& a, const hal::RobotPoint& b, int i, int n) const noexcept;
  // Beyond the picture's edges (above the horizon is inside: not ground, not "nothing to say").
  [[nodiscard]] bool outside(double x, double y) const noexcept;
  // One sample: image point c of the centre line, unit normal (nx, ny), expected half width h.
  [[nodiscard]] bool looks_like_line(double cx, double cy, double nx, double ny, double h) const noexcept;

  const ClassImage& classes_;
  const hal::CameraIntrinsics& k_;
  const hal::CameraPose& pose_;
  LineCheckParams params_;
};

}  // namespace ringlet::vision
