#pragma once
// What one frame of vision costs on the target board, from the work the pipeline counted: a pure
// function of the frame, the head posture and the degrade level, never of a clock. The executive
// judges the vision task's budget on this figure in lockstep, so a simulated run degrades (or
// not) the same way on every host and under any load; on the real clock it judges measured time.
//
// The coefficients are the development host's measured CPU time per unit of work (stage
// benchmarks of ringlet_bench_vision, see cost_model.cpp) times board_slowdown, the assumed ratio
// of a NAO-class ARM core to that host. They are a model: the timing table prints it beside the
// measured time (MODEL-P99 against CPU-P99) and BM_Pipeline beside the benchmark's, so a drift shows.
#include <cstdint>

#include "ringlet/hal/time.hpp"

namespace ringlet::vision {

/// The work one process() call did, counted as it went.
struct WorkCount {
  std::int64_t classified_pixels = 0;  // pixels given a colour class
  std::int64_t ball_samples = 0;       // class-image samples the ball detector looked at
  std::int64_t scanned_pixels = 0;     // pixels walked by the scan lines (vertical + horizontal)
  std::int64_t candidates = 0;         // scan points offered to RANSAC
  std::int64_t point_tests = 0;        // RANSAC trials × points each trial tested, plus the draws of
                                       // their second points; and the field marks'
  // Appended (issue 10), so that older brace-initialised counts keep their meaning:
  std::int64_t colour_samples = 0;     // pixels the adaptive field-colour estimate sampled
  std::int64_t colour_rebuilds = 0;    // adaptive classification tables rebuilt (0 or 1 per frame)
  std::int64_t robot_samples = 0;      // class-image samples the robot candidate scan looked at
  std::int64_t ball_windows = 0;       // HOG/SVM classifications of ball candidates (resample, HOG, dot product)
  std::int64_t robot_windows = 0;      // HOG/SVM classifications of robot candidates
  std::int64_t circle_tests = 0;       // the centre circle's trials × sample points × 3 walks
};

struct CostModel {
  double board_slowdown = 4.0;      // NAO-class ARM core / this host (assumed; recalibrate on the board)
  double fixed_ns = 0.0;            // per frame: horizon, bookkeeping, posting
  double per_classified_pixel_ns = 0.0;
  double per_ball_sample_ns = 0.0;
  double per_scanned_pixel_ns = 0.0;
  double per_candidate_ns = 0.0;
  double per_point_test_ns = 0.0;
  double per_colour_sample_ns = 0.0;
  double per_colour_rebuild_ns = 0.0;
  double per_robot_sample_ns = 0.0;
  double per_ball_window_ns = 0.0;
  double per_robot_window_ns = 0.0;
  double per_circle_test_ns = 0.0;
};

/// One frame's modelled time on the development host, row by row (before the board factor): what
/// each stage's share is, to set beside the stage's measured time.
struct HostCost {
  double fixed = 0.0;
  double classified_pixels = 0.0, ball_samples = 0.0, scanned_pixels = 0.0, candidates = 0.0, point_tests = 0.0;
  double colour_samples = 0.0, colour_rebuilds = 0.0, robot_samples = 0.0, ball_windows = 0.0, robot_windows = 0.0;
  double circle_tests = 0.0;
  /// Their sum, in this order (modelled_cost's, so that every target adds the same way).
  [[nodiscard]] double total() const noexcept {
    return fixed + classified_pixels + ball_samples + scanned_pixels + candidates + point_tests + colour_samples +
           colour_rebuilds + robot_samples + ball_windows + robot_windows + circle_tests;
  }
};

/// The shipped model (coefficients measured on the development host).
[[nodiscard]] CostModel default_cost_model() noexcept;

/// `work`'s modelled host time, row by row.
[[nodiscard]] HostCost host_cost(const WorkCount& work, const CostModel& model = default_cost_model()) noexcept;

/// Modelled board time for `work`, in whole nanoseconds: host_cost(work).total() × board_slowdown.
[[nodiscard]] hal::Nanos modelled_cost(const WorkCount& work, const CostModel& model = default_cost_model()) noexcept;

}  // namespace ringlet::vision
