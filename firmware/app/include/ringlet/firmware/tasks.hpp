#pragma once
// The firmware's tasks, one executive task each, in table order:
//   sense → fsm → actuate → telemetry → whiteboard
// Each is a small adapter between the executive and one piece of work. Algorithms talk only
// through the whiteboard; sense writes it from the HAL, actuate reads it back out to the HAL.
#include "ringlet/behaviour/llfsm/schedule.hpp"
#include "ringlet/behaviour/machines/mission.hpp"
#include "ringlet/behaviour/waypoint_mission.hpp"
#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/cycle_state.hpp"
#include "ringlet/firmware/task_costs.hpp"
#include "ringlet/firmware/telemetry.hpp"
#include "ringlet/hal/robot.hpp"
#include "ringlet/sim_hal/sim_robot.hpp"
#include "ringlet/vision/pipeline.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::executive {
class Executive;
}

namespace ringlet::firmware {

using hal::Nanos;

/// HAL sensors → CycleState and the whiteboard (Pose, LaserSummary). On the simulated robot this
/// is also what advances the world and keeps the true ball for scoring; without a camera it posts
/// that true ball as the BallBelief, marked `simulated` (with a camera, vision posts it).
class SenseTask final : public executive::Task {
 public:
  SenseTask(hal::Sensors& sensors, CycleState& state, wb::Whiteboard& board, const sim_hal::SimRobot* truth,
            bool post_true_ball) noexcept
      : sensors_(sensors), state_(state), board_(board), truth_(truth), post_true_ball_(post_true_ball) {}
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] Nanos modelled_cost() const noexcept override { return task_costs::kSense; }

 private:
  hal::Sensors& sensors_;
  CycleState& state_;
  wb::Whiteboard& board_;
  const sim_hal::SimRobot* truth_;
  bool post_true_ball_;
};

/// What vision did over the run (for the summary).
struct VisionStats {
  std::uint64_t frames = 0;             // camera frames processed
  std::uint64_t with_lines = 0;         // ... in which at least one line was found
  std::uint64_t lines = 0;              // lines found in all
  std::uint64_t with_ball = 0;          // ... in which the ball was found
  std::uint64_t cut = 0;                // ... in which the deadline cut work short
  std::uint64_t degraded = 0;           // ... processed at a degrade level above 0
  std::uint64_t bad_frames = 0;         // frames of the wrong size (nothing done)
  std::uint64_t missed_frames = 0;      // sequence gaps: frames the camera had that were never processed
};

/// How the vision task honours its deadline. On the real clock the pipeline stops work when the
/// task's time is up. In lockstep simulation it never does: a cut there would depend on how busy
/// the host is, and a simulated run must be bit-identical for a seed; the executive still
/// measures the task against its budget and reports (and acts on) overruns.
enum class VisionDeadline : std::uint8_t { kNone, kWall, kCpu };

/// Camera → vision pipeline → whiteboard (FieldLines, BallBelief). Runs when the table says
/// (every camera period); processes the newest frame once, with the head posture of its capture
/// time, inside the task's deadline (and at the executive's degrade level).
class VisionTask final : public executive::Task {
 public:
  VisionTask(hal::Camera& camera, vision::VisionPipeline& pipeline, const CycleState& state, wb::Whiteboard& board,
             VisionDeadline deadline) noexcept
      : camera_(camera), pipeline_(pipeline), state_(state), board_(board), deadline_(deadline) {}
  void run(const executive::TaskContext& ctx) noexcept override;
  /// vision::modelled_cost of the frame processed, or a small fixed cost when there was none.
  [[nodiscard]] Nanos modelled_cost() const noexcept override { return cost_; }
  [[nodiscard]] const VisionStats& stats() const noexcept { return stats_; }

 private:
  hal::Camera& camera_;
  vision::VisionPipeline& pipeline_;
  const CycleState& state_;
  wb::Whiteboard& board_;
  VisionDeadline deadline_;
  bool have_frame_ = false;
  std::uint64_t last_sequence_ = 0;
  Nanos cost_{0};
  VisionStats stats_{};
};

/// The LLFSM schedule: one turn of every machine per activation, on the executive's clock.
class FsmTask final : public executive::Task {
 public:
  explicit FsmTask(behaviour::llfsm::Schedule& schedule) noexcept : schedule_(schedule) {}
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] Nanos modelled_cost() const noexcept override;

 private:
  behaviour::llfsm::Schedule& schedule_;
};

/// Whiteboard MotionCommand and HeadCommand → HAL actuators. `stop` means v = 0.
class ActuateTask final : public executive::Task {
 public:
  ActuateTask(hal::Actuators& actuators, const wb::Whiteboard& board) noexcept
      : actuators_(actuators), board_(board) {}
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] Nanos modelled_cost() const noexcept override { return task_costs::kActuate; }

 private:
  hal::Actuators& actuators_;
  const wb::Whiteboard& board_;
};

/// Records the run (trajectory every `every_frames`, collision events, goal times, how well the
/// head follows the ball) and ends the run once the Mission machine is Done.
class TelemetryTask final : public executive::Task {
 public:
  TelemetryTask(Telemetry& telemetry, const behaviour::WaypointMission& mission,
                const behaviour::machines::Mission& machine, const CycleState& state, int every_frames) noexcept
      : telemetry_(telemetry),
        mission_(mission),
        machine_(machine),
        state_(state),
        every_(static_cast<std::uint64_t>(every_frames)) {}
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] Nanos modelled_cost() const noexcept override { return task_costs::kTelemetry; }

 private:
  Telemetry& telemetry_;
  const behaviour::WaypointMission& mission_;
  const behaviour::machines::Mission& machine_;
  const CycleState& state_;
  std::uint64_t every_;
  bool was_colliding_ = false;
};

/// The cycle's one defined point for whiteboard subscriptions (dispatch, in type-id order), and
/// once a second the executive's counters as ExecutiveTiming.
class WhiteboardTask final : public executive::Task {
 public:
  explicit WhiteboardTask(wb::Whiteboard& board) noexcept : board_(board) {}
  /// The executive is built after its tasks; the stack attaches it before the first frame.
  void attach(const executive::Executive& executive) noexcept { executive_ = &executive; }
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] Nanos modelled_cost() const noexcept override { return task_costs::kWhiteboard; }

 private:
  wb::Whiteboard& board_;
  const executive::Executive* executive_ = nullptr;
};

}  // namespace ringlet::firmware
