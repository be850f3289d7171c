#pragma once
// The whole controller for one configuration: the backend chosen by robot.backend (built by the
// backend factory), the clocks, the whiteboard, the LLFSM schedule (BallTracker, Mission, Safety),
// the tasks the table names (built through the task registry) and the executive. Everything is
// allocated here, at start-up; running it allocates nothing. The binary, the tests and the tools
// all build the controller this way.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ringlet/behaviour/llfsm/schedule.hpp"
#include "ringlet/behaviour/llfsm/whiteboard_bus.hpp"
#include "ringlet/behaviour/machines/ball_tracker.hpp"
#include "ringlet/behaviour/machines/navigate.hpp"
#include "ringlet/behaviour/machines/plan_execute.hpp"
#include "ringlet/behaviour/machines/mission.hpp"
#include "ringlet/behaviour/machines/safety.hpp"
#include "ringlet/executive/event_log.hpp"
#include "ringlet/executive/executive.hpp"
#include "ringlet/executive/spsc_queue.hpp"
#include "ringlet/firmware/backend_factory.hpp"
#include "ringlet/firmware/config.hpp"
#include "ringlet/firmware/experience_log.hpp"
#include "ringlet/firmware/remote_link.hpp"
#include "ringlet/firmware/task_registry.hpp"
#include "ringlet/firmware/telemetry.hpp"
#include "ringlet/firmware/truth_score.hpp"
#include "ringlet/hal/monotonic_clock.hpp"
#include "ringlet/hal/recording_robot.hpp"
#include "ringlet/hal/virtual_clock.hpp"
#include "ringlet/whiteboard/message_log.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

class FirmwareStack {
 public:
  /// Builds the robot, the machines, the tasks of the table (from `registry`) and the executive.
  /// `opencv_camera` makes [camera] backend "opencv" (firmware/camera_opencv): null in a program
  /// built without it, which then refuses that backend. Throws ConfigError or
  /// executive::TableError on bad input.
  explicit FirmwareStack(const FirmwareConfig& config, const TaskRegistry& registry = production_tasks(),
                         OpenCvCameraMaker opencv_camera = nullptr);
  /// The same around a robot built elsewhere instead of the backend's (config.backend names what
  /// it is): e.g. a CanRobot over one end of a socketpair whose other end a software board serves.
  FirmwareStack(const FirmwareConfig& config, std::unique_ptr<hal::Robot> backend,
                const TaskRegistry& registry = production_tasks(), OpenCvCameraMaker opencv_camera = nullptr);
  ~FirmwareStack();
  FirmwareStack(const FirmwareStack&) = delete;
  FirmwareStack& operator=(const FirmwareStack&) = delete;

  [[nodiscard]] const FirmwareConfig& config() const noexcept { return config_; }
  [[nodiscard]] executive::Executive& executive() noexcept { return *executive_; }
  [[nodiscard]] const executive::Executive& executive() const noexcept { return *executive_; }
  /// The robot the tasks drive: the backend's, or the recorder wrapped round it (--record).
  [[nodiscard]] hal::Robot& robot() noexcept { return recorder_ ? *recorder_ : *robot_; }
  [[nodiscard]] const hal::Robot& robot() const noexcept { return recorder_ ? *recorder_ : *robot_; }
  [[nodiscard]] hal::Clock& clock() noexcept;
  [[nodiscard]] executive::EventLog& events() noexcept { return events_; }
  [[nodiscard]] const Telemetry& telemetry() const noexcept { return telemetry_; }
  [[nodiscard]] wb::Whiteboard& whiteboard() noexcept { return board_; }
  [[nodiscard]] const behaviour::llfsm::Schedule& schedule() const noexcept { return schedule_; }
  /// Every FsmStatus posted, delivered by a whiteboard subscription at the whiteboard task's
  /// dispatch and queued here for the log drain (full: dropped and counted).
  using FsmStatusLog = executive::SpscQueue<wb::FsmStatus, 4096>;
  [[nodiscard]] FsmStatusLog& fsm_status_log() noexcept { return *fsm_status_log_; }
  [[nodiscard]] std::uint64_t fsm_status_seen() const noexcept { return fsm_status_seen_; }
  /// Ground truth for the report, when the backend has any (the simulator), else null.
  [[nodiscard]] const hal::GroundTruth* truth() const noexcept { return robot_->ground_truth(); }
  /// The run scored against ground truth, when there is any, else null.
  [[nodiscard]] const TruthScore* truth_score() const noexcept { return truth_score_ ? &*truth_score_ : nullptr; }

  /// The experiences the planner recorded in this run ([planner] record, learn_online).
  [[nodiscard]] const ExperienceLog& experiences() const noexcept { return experiences_; }

  /// The whiteboard on DDS ([remote] enabled), else null.
  [[nodiscard]] RemoteLink* remote() noexcept { return remote_.get(); }
  [[nodiscard]] const RemoteLink* remote() const noexcept { return remote_.get(); }

  /// Ends the --record and --wb-log logs (after the run): one line per log that failed, else empty.
  [[nodiscard]] std::vector<std::string> finish_logs() noexcept;

  /// Frames in `seconds` of schedule time (rounded up).
  [[nodiscard]] std::uint64_t frames_for(double seconds) const noexcept;

 private:
  FirmwareConfig config_;
  std::unique_ptr<hal::Robot> robot_;
  std::unique_ptr<hal::RecordingRobot> recorder_;  // --record
  hal::VirtualClock virtual_clock_;
  hal::MonotonicClock monotonic_clock_;
  hal::ThreadStopwatch stopwatch_;
  executive::EventLog events_;
  wb::Whiteboard board_;
  std::unique_ptr<FsmStatusLog> fsm_status_log_;
  std::uint64_t fsm_status_seen_ = 0;
  std::unique_ptr<wb::MessageLogger> message_log_;  // --wb-log
  Telemetry telemetry_;
  ExperienceLog experiences_;
  behaviour::machines::BallTracker ball_tracker_;
  behaviour::machines::Mission mission_machine_;
  behaviour::machines::Navigate navigate_machine_;  // scheduled instead of Mission with [mission] drive = "navigate"
  behaviour::machines::PlanExecute plan_execute_;  // ... with drive = "pddl"
  behaviour::machines::Safety safety_;
  behaviour::llfsm::WhiteboardFsmBus fsm_bus_;
  behaviour::llfsm::Schedule schedule_;
  std::unique_ptr<hal::Camera> owned_camera_;  // [camera] backend "opencv"
  const executive::Executive* executive_view_ = nullptr;  // what TaskServices hands the tasks
  std::vector<std::unique_ptr<executive::Task>> tasks_;   // in table order
  std::unique_ptr<executive::Executive> executive_;
  std::optional<TruthScore> truth_score_;
  std::unique_ptr<RemoteLink> remote_;  // last: it reads the whiteboard until it is gone
};

}  // namespace ringlet::firmware
