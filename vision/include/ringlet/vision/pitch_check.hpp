#pragma once
// The head pitch the field lines agree with.
//
// Every SPL field line runs along the field or across it, so any two lines are parallel on the
// ground or at right angles. Seen through a camera model whose pitch is off (a camera mounted a
// degree or two off, a torso lean the inertial unit misreads, head angles guessed for a photo),
// the lines' ground projections are not: points far away move more than near ones, parallel lines
// converge and corners open. A pitch 3° off costs about 0.13 of line F1 and 6° about 0.3
// (vision/README.md, "The head pitch from the lines"), because the width check and the ground
// geometry then expect the wrong paint.
//
// estimate_pitch_offset searches the offset to the head pitch (the joint next to the camera: a
// camera mounted pitched is the same rotation) that brings the detected lines' ground directions
// closest to parallel or perpendicular, pair by pair. A grid search over the whole range, for
// calibration and checking a photo (ringlet-vision --auto-pitch); not on the cycle path.
#include <array>
#include <span>

#include "ringlet/hal/camera.hpp"
#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/vision/pipeline.hpp"

namespace ringlet::vision {

struct ImageSegment {
  hal::Pixel a{};
  hal::Pixel b{};
};

struct PitchCheckParams {
  double range_deg = 8.0;        // offsets searched: −range … +range
  double step_deg = 0.05;
  double min_length_px = 40.0;   // shorter segments give too noisy a direction
  // Two segments within this angle in the picture and this close to each other's line are
  // pieces of one line: parallel at any pitch, they tell nothing.
  double collinear_deg = 3.0;
  double collinear_px = 10.0;
  // A pitch can square any one pair; only a second pair checks it. And lines that cannot be
  // brought within this of square are not all field lines (an arc piece, a goal post's edge).
  int min_pairs = 2;
  double max_residual_deg = 1.5;
};

struct PitchCheck {
  bool valid = false;                  // min_pairs pairs that are not one line, squared to within
                                       // max_residual_deg at an offset inside the range
  double offset_deg = 0.0;             // add to the head pitch (positive: the camera looks further down)
  double residual_deg = 0.0;           // the pairs' weighted RMS departure from parallel or square, at the offset
  double residual_at_given_deg = 0.0;  // the same at the given pitch (offset 0)
  int segments = 0;                    // long enough, and on the ground at the given pitch
  int pairs = 0;                       // pairs that are not one line (of the segments kept)
  int dropped = 0;                     // segments left out as disagreeing with the rest
};

/// The head-pitch offset that makes `segments` (picture coordinates, e.g. detected field lines)
/// most nearly parallel or perpendicular on the ground. Pairs are weighted by the geometric mean
/// of their lengths in the picture. While no offset squares them to max_residual_deg, the segment
/// whose loss helps most is left out (at most a third of them, keeping min_pairs pairs). Only segments on the ground at the given pitch count, and only
/// offsets at which all of them stay on it are searched. Allocates nothing.
[[nodiscard]] PitchCheck estimate_pitch_offset(std::span<const ImageSegment> segments, const hal::CameraIntrinsics& k,
                                               const hal::CameraMount& mount, const hal::CameraPosture& posture,
                                               const PitchCheckParams& params = {}) noexcept;

/// What correct_head_pitch found: the posture to use and each round's check.
struct PitchCorrection {
  hal::CameraPosture posture{};
  std::array<PitchCheck, 2> rounds{};
  int round_count = 0;
  /// The first round's estimate was made (and applied).
  [[nodiscard]] bool corrected() const noexcept { return round_count > 0 && rounds[0].valid; }
};

/// Runs `frame` at `posture`, estimates the head-pitch offset from the lines found and, when the
/// estimate is valid and at least 0.1°, runs again at the corrected pitch (kept within the NAO's
/// range) and checks once more. Each run forgets the colour history first, as a fresh run. No
/// deadline: for tools, not the cycle.
[[nodiscard]] PitchCorrection correct_head_pitch(VisionPipeline& pipeline, const hal::FrameView& frame,
                                                 const hal::CameraPosture& posture,
                                                 const PitchCheckParams& params = {}) noexcept;

}  // namespace ringlet::vision
