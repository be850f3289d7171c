#pragma once
// The penalty and centre marks (painted crosses) scored on their own.
//
//   Truth: the frame's crosses. ringlet-dataset lists each bar of a cross as a marking with its
//   world ends; a marking at most kCrossBarMaxM long in the world is a bar, and bars sharing a
//   world centre are one cross, whose centre in the robot frame comes from the frame's pose. A
//   cross is EXPECTED when one of its bars is at least min_bar_px long in the picture (the rule
//   that makes a line piece count for the line recall); a smaller one is "don't care".
//   A detected mark MATCHES a cross when its centre is within max_centre_error_m of it (each
//   cross matched once, nearest first). Precision: matching detections / detections (one that
//   matches only a don't-care cross is left out); recall: expected crosses matched / expected.
//   The counts are CircleCounts' (precision, recall, centre error), with no radius.
//
//   The bars are painted lines, so the line score sees them too: the evaluation adds a found
//   mark's two bars (at its orientation) to the line detections (evaluation.cpp).
#include <span>

#include "ringlet/hal/geometry.hpp"
#include "circle_score.hpp"

namespace ringlet::vision::evaluate {

inline constexpr double kCrossBarMaxM = 0.11;  // SPL bars are 0.10 m; every field line is longer

struct TruthMark {
  hal::RobotPoint centre{};     // robot frame
  double longest_bar_px = 0.0;  // the longest visible piece of its bars in the picture
};

struct MarkMatchParams {
  double max_centre_error_m = 0.15;
  double min_bar_px = 20.0;
};

/// One frame's detected mark centres (robot frame) against its crosses.
[[nodiscard]] CircleCounts score_marks(std::span<const hal::RobotPoint> detected, std::span<const TruthMark> truth,
                                       const MarkMatchParams& params = {});

}  // namespace ringlet::vision::evaluate
