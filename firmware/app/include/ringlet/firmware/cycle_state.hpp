#pragma once
// What the firmware's own tasks keep of one frame besides the whiteboard: the raw sensor reading
// (telemetry records it) and, on the simulated robot, the ground truth that scores the run. The
// algorithms (the LLFSMs) never see this: they read and write the whiteboard only.
#include <array>
#include <cstddef>
#include <optional>

#include "ringlet/hal/geometry.hpp"
#include "ringlet/hal/sensors.hpp"

namespace ringlet::firmware {

/// The head joints of the last few frames, so that a camera frame is projected with the head
/// posture at its capture time, not at the time it is processed.
class HeadHistory {
 public:
  void record(hal::Nanos stamp, const hal::HeadJoints& head) noexcept {
    samples_[next_ % samples_.size()] = {stamp, head};
    ++next_;
  }
  /// The posture recorded closest to `when` (the newest when nothing was recorded).
  [[nodiscard]] hal::HeadJoints at(hal::Nanos when) const noexcept {
    const std::size_t n = next_ < samples_.size() ? next_ : samples_.size();
    hal::HeadJoints best{};
    hal::Nanos best_gap = hal::Nanos::max();
    for (std::size_t i = 0; i < n; ++i) {
      const hal::Nanos gap = samples_[i].stamp > when ? samples_[i].stamp - when : when - samples_[i].stamp;
      if (gap < best_gap) {
        best_gap = gap;
        best = samples_[i].head;
      }
    }
    return best;
  }

 private:
  struct Sample {
    hal::Nanos stamp{0};
    hal::HeadJoints head{};
  };
  std::array<Sample, 16> samples_{};
  std::size_t next_ = 0;
};

struct CycleState {
  hal::SensorFrame sensors{};
  bool sensors_ok = false;
  std::optional<hal::RobotPoint> true_ball;  // simulator ground truth (sim backend only)
  HeadHistory head_history;
};

}  // namespace ringlet::firmware
