#pragma once
// Records the run from the whiteboard (the trajectory every `trajectory_every` frames, bumper
// contacts, odometry, the mission's progress) and ends the run once MissionStatus says the
// mission is done.
#include <memory>

#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"
#include "ringlet/firmware/telemetry.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

class TelemetryTask final : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{"telemetry", kTypeNames<wb::Pose, wb::BodyState, wb::MissionStatus>,
                                                kNoTypes, here()};
  static constexpr hal::Nanos kModelledCost{4'000};

  static std::unique_ptr<executive::Task> make(TaskServices& services);
  TelemetryTask(Telemetry& telemetry, const wb::Whiteboard& board, int every_frames) noexcept
      : telemetry_(telemetry), board_(board), every_(static_cast<std::uint64_t>(every_frames)) {}
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] hal::Nanos modelled_cost() const noexcept override { return kModelledCost; }

 private:
  Telemetry& telemetry_;
  const wb::Whiteboard& board_;
  std::uint64_t every_;
  bool was_touching_ = false;
};

}  // namespace ringlet::firmware
