#pragma once
// Camera → vision pipeline → whiteboard (FieldLines, BallBelief, RobotDetections). Runs when the table says (every
// camera period); processes the newest frame once, with the camera posture of its capture time
// (head joints and torso tilt) read back from the whiteboard's HeadPosture generations, inside the
// task's deadline (and at the executive's degrade level).
#include <memory>

#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"
#include "ringlet/hal/camera.hpp"
#include "ringlet/vision/pipeline.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

/// How the vision task honours its deadline. On the real clock the pipeline stops work when the
/// task's time is up. In lockstep simulation it never does: a cut there would depend on how busy
/// the host is, and a simulated run must be bit-identical for a seed; the executive judges the
/// task on its modelled cost instead.
enum class VisionDeadline : std::uint8_t { kNone, kWall, kCpu };

class VisionTask final : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{"vision", kTypeNames<wb::HeadPosture>,
                                                kTypeNames<wb::FieldLines, wb::BallBelief, wb::RobotDetections>,
                                                here()};
  /// An activation that finds no new camera frame.
  static constexpr hal::Nanos kNoFrameCost{2'000};

  /// ConfigError when there is no camera or the colour table or a HOG/SVM model cannot be loaded.
  static std::unique_ptr<executive::Task> make(TaskServices& services);
  VisionTask(hal::Camera& camera, std::unique_ptr<vision::VisionPipeline> pipeline, wb::Whiteboard& board,
             VisionDeadline deadline, VisionStats& stats) noexcept;
  void run(const executive::TaskContext& ctx) noexcept override;
  /// vision::modelled_cost of the frame processed, or kNoFrameCost when there was none.
  [[nodiscard]] hal::Nanos modelled_cost() const noexcept override { return cost_; }
  /// The frame's line search was cut (by the deadline or, in lockstep, the modelled budget;
  /// vision::CutStats::lines_cut).
  [[nodiscard]] bool overloaded() const noexcept override { return overloaded_; }

 private:
  [[nodiscard]] hal::CameraPosture posture_at(hal::Nanos when) const noexcept;
  /// Each stage's modelled board time into stats_.stage_model (the mission report's breakdown).
  void record_stage_costs(const vision::WorkCount& work) noexcept;

  hal::Camera& camera_;
  std::unique_ptr<vision::VisionPipeline> pipeline_;
  wb::Whiteboard& board_;
  VisionDeadline deadline_;
  VisionStats& stats_;
  bool have_frame_ = false;
  std::uint64_t last_sequence_ = 0;
  hal::Nanos cost_{0};
  bool overloaded_ = false;
};

/// The vision pipeline for [camera] and [vision] (its colour table and HOG/SVM models loaded: ConfigError if not).
[[nodiscard]] std::unique_ptr<vision::VisionPipeline> make_vision(const FirmwareConfig& config);

}  // namespace ringlet::firmware
