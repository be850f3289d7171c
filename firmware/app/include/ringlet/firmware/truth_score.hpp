#pragma once
// Scoring the run against ground truth, when the backend has any (the simulator): how well the
// head follows the true ball. It watches each frame from outside the task table
// (executive::FrameObserver) and reads the whiteboard and hal::GroundTruth only; nothing the
// controller does depends on it.
#include <cstdint>

#include "ringlet/executive/executive.hpp"
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

class TruthScore final : public executive::FrameObserver {
 public:
  TruthScore(const hal::GroundTruth& truth, const wb::Whiteboard& board) noexcept : truth_(truth), board_(board) {}
  void frame_done(std::uint64_t frame, hal::Nanos frame_start) noexcept override;
  [[nodiscard]] const HeadTracking& head_tracking() const noexcept { return head_; }

 private:
  const hal::GroundTruth& truth_;
  const wb::Whiteboard& board_;
  HeadTracking head_{};
};

}  // namespace ringlet::firmware
