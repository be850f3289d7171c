#pragma once
// The whole controller for one configuration: the backend chosen by robot.backend, the clocks,
// the whiteboard, the LLFSM schedule (BallTracker, Mission, Safety), the tasks and the executive
// with its table. Everything is allocated here, at start-up; running
// it allocates nothing. The binary, the tests and the tools all build the controller this way.
#include <cstdint>
#include <memory>
#include <optional>

#include "ringlet/behaviour/llfsm/schedule.hpp"
#include "ringlet/behaviour/llfsm/whiteboard_bus.hpp"
#include "ringlet/behaviour/machines/ball_tracker.hpp"
#include "ringlet/behaviour/machines/mission.hpp"
#include "ringlet/behaviour/machines/safety.hpp"
#include "ringlet/behaviour/waypoint_mission.hpp"
#include "ringlet/executive/event_log.hpp"
#include "ringlet/executive/executive.hpp"
#include "ringlet/executive/spsc_queue.hpp"
#include "ringlet/firmware/config.hpp"
#include "ringlet/firmware/cycle_state.hpp"
#include "ringlet/firmware/tasks.hpp"
#include "ringlet/firmware/telemetry.hpp"
#include "ringlet/hal/monotonic_clock.hpp"
#include "ringlet/hal/virtual_clock.hpp"
#include "ringlet/sim_hal/sim_robot.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

class FirmwareStack {
 public:
  /// Loads the world (sim backend), builds the robot, tasks and executive. Throws
  /// sim_hal::WorldError, ConfigError or executive::TableError on bad input.
  explicit FirmwareStack(const FirmwareConfig& config);
  ~FirmwareStack();
  FirmwareStack(const FirmwareStack&) = delete;
  FirmwareStack& operator=(const FirmwareStack&) = delete;

  [[nodiscard]] const FirmwareConfig& config() const noexcept { return config_; }
  [[nodiscard]] executive::Executive& executive() noexcept { return *executive_; }
  [[nodiscard]] const executive::Executive& executive() const noexcept { return *executive_; }
  [[nodiscard]] hal::Robot& robot() noexcept { return *robot_; }
  [[nodiscard]] hal::Clock& clock() noexcept;
  [[nodiscard]] executive::EventLog& events() noexcept { return events_; }
  [[nodiscard]] const Telemetry& telemetry() const noexcept { return telemetry_; }
  [[nodiscard]] const behaviour::WaypointMission& mission() const noexcept { return mission_; }
  [[nodiscard]] wb::Whiteboard& whiteboard() noexcept { return board_; }
  [[nodiscard]] const behaviour::llfsm::Schedule& schedule() const noexcept { return schedule_; }
  /// Every FsmStatus posted, delivered by a whiteboard subscription at the whiteboard task's
  /// dispatch and queued here for the log drain (full: dropped and counted).
  using FsmStatusLog = executive::SpscQueue<wb::FsmStatus, 4096>;
  [[nodiscard]] FsmStatusLog& fsm_status_log() noexcept { return *fsm_status_log_; }
  [[nodiscard]] std::uint64_t fsm_status_seen() const noexcept { return fsm_status_seen_; }
  /// The head camera ([camera] enabled) and what vision made of it, else null.
  [[nodiscard]] hal::Camera* camera() noexcept { return camera_; }
  [[nodiscard]] const VisionTask* vision() const noexcept { return vision_task_ ? &*vision_task_ : nullptr; }
  /// The simulated robot when robot.backend is "sim", else null.
  [[nodiscard]] const sim_hal::SimRobot* sim_robot() const noexcept { return sim_; }

  /// Frames in `seconds` of schedule time (rounded up).
  [[nodiscard]] std::uint64_t frames_for(double seconds) const noexcept;

 private:
  FirmwareConfig config_;
  std::unique_ptr<hal::Robot> robot_;
  const sim_hal::SimRobot* sim_ = nullptr;
  hal::VirtualClock virtual_clock_;
  hal::MonotonicClock monotonic_clock_;
  hal::ThreadStopwatch stopwatch_;
  executive::EventLog events_;
  wb::Whiteboard board_;
  std::unique_ptr<FsmStatusLog> fsm_status_log_;
  std::uint64_t fsm_status_seen_ = 0;
  CycleState state_;
  behaviour::WaypointMission mission_;
  Telemetry telemetry_;
  behaviour::machines::BallTracker ball_tracker_;
  behaviour::machines::Mission mission_machine_;
  behaviour::machines::Safety safety_;
  behaviour::llfsm::WhiteboardFsmBus fsm_bus_;
  behaviour::llfsm::Schedule schedule_;
  hal::Camera* camera_ = nullptr;              // the robot's, or owned_camera_
  std::unique_ptr<hal::Camera> owned_camera_;  // [camera] backend "opencv"
  std::unique_ptr<vision::VisionPipeline> pipeline_;
  std::optional<VisionTask> vision_task_;
  SenseTask sense_;
  FsmTask fsm_;
  ActuateTask actuate_;
  TelemetryTask telemetry_task_;
  WhiteboardTask whiteboard_task_;
  std::unique_ptr<executive::Executive> executive_;
};

/// The backend named by config.backend. "sim" loads config.world; "can" is refused with a
/// ConfigError until the SocketCAN backend exists.
[[nodiscard]] std::unique_ptr<hal::Robot> make_robot(const FirmwareConfig& config);

/// The camera [camera] asks for when it is not the robot's own (backend "opencv"), else null.
[[nodiscard]] std::unique_ptr<hal::Camera> make_camera(const FirmwareConfig& config, const hal::Clock& clock);

/// The vision pipeline for [camera] and [vision] (its colour table loaded: ConfigError if not).
[[nodiscard]] std::unique_ptr<vision::VisionPipeline> make_vision(const FirmwareConfig& config);

/// Whiteboard types the firmware's tasks (not machines) provide: sense posts them.
inline constexpr std::string_view kTaskProvidedTypes[] = {"Pose", "LaserSummary", "BallBelief"};

/// The world's goals as the behaviour layer's waypoints (empty for real backends).
[[nodiscard]] std::vector<behaviour::Waypoint> mission_goals(const hal::Robot& robot);

}  // namespace ringlet::firmware
