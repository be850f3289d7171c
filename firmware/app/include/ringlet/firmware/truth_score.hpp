#pragma once
// Scoring the run against ground truth, when the backend has any (the simulator): how well the
// head follows the true ball. It watches each frame from outside the task table
// (executive::FrameObserver) and reads the whiteboard and hal::GroundTruth only; nothing the
// controller does depends on it.
#include <array>
#include <cstdint>

#include "ringlet/executive/executive.hpp"
#include "ringlet/firmware/telemetry.hpp"
#include "ringlet/hal/ground_truth.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

/// How well the head's measured yaw follows the true direction of the ball (ground truth only). Frames
/// where the ball lies beyond the neck's reach, and the first second (the head starts ahead), do
/// not count.
struct HeadTracking {
  static constexpr double kNeckLimit = 2.0;      // rad, as the ball tracker clamps
  static constexpr double kOnTarget = 0.0873;    // rad: 5 degrees
  std::uint64_t frames = 0;
  std::uint64_t on_target = 0;
  double sum_error = 0.0;  // rad
  double max_error = 0.0;  // rad

  [[nodiscard]] double on_target_share() const noexcept {
    return frames == 0 ? 0.0 : static_cast<double>(on_target) / static_cast<double>(frames);
  }
  [[nodiscard]] double mean_error() const noexcept {
    return frames == 0 ? 0.0 : sum_error / static_cast<double>(frames);
  }
};

/// How far the localization's pose (Localization on the whiteboard) is from the true pose, every
/// frame once it is posted: mean and 95th percentile (from fixed histograms: 5 mm and 0.1° bins,
/// nothing allocated), position and heading, over all frames and over the frames where Pose was
/// valid (the controller drove on it).
struct LocalizationScore {
  static constexpr double kPositionBin = 0.005;  // m
  static constexpr double kHeadingBin = 0.1;     // deg
  std::array<std::uint32_t, 2000> position{};    // the last bin takes everything beyond 10 m
  std::array<std::uint32_t, 1801> heading{};
  std::uint64_t frames = 0;
  std::uint64_t valid_frames = 0;  // Pose.valid
  double sum_position = 0.0, sum_heading_deg = 0.0, max_position = 0.0;
  double sum_valid_position = 0.0;
  // Frames where Pose was valid but more than kWrong off the truth: the run's longest stretch of
  // them, and when the estimate was last not good (invalid, or more than kWrong off).
  static constexpr double kWrong = 0.5;  // m
  std::uint64_t valid_wrong_frames = 0, longest_valid_wrong = 0, current_valid_wrong = 0;
  hal::Nanos last_not_good{-1};

  [[nodiscard]] double mean_position() const noexcept { return frames == 0 ? 0.0 : sum_position / static_cast<double>(frames); }
  [[nodiscard]] double mean_heading_deg() const noexcept {
    return frames == 0 ? 0.0 : sum_heading_deg / static_cast<double>(frames);
  }
  [[nodiscard]] double p95_position() const noexcept;
  [[nodiscard]] double p95_heading_deg() const noexcept;
};

class TruthScore final : public executive::FrameObserver {
 public:
  /// `telemetry`: where the true pose goes every `every` frames once the localization has posted,
  /// beside the estimated trajectory (null, or no localization recording: nowhere).
  TruthScore(const hal::GroundTruth& truth, const wb::Whiteboard& board, Telemetry* telemetry = nullptr,
             int every = 10) noexcept
      : truth_(truth), board_(board), telemetry_(telemetry), every_(static_cast<std::uint64_t>(every > 0 ? every : 1)) {}
  void frame_done(std::uint64_t frame, hal::Nanos frame_start) noexcept override;
  [[nodiscard]] const HeadTracking& head_tracking() const noexcept { return head_; }
  [[nodiscard]] const LocalizationScore& localization() const noexcept { return loc_; }

 private:
  const hal::GroundTruth& truth_;
  const wb::Whiteboard& board_;
  Telemetry* telemetry_;
  std::uint64_t every_;
  HeadTracking head_{};
  LocalizationScore loc_{};
};

}  // namespace ringlet::firmware
