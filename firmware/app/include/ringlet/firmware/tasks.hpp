#pragma once
// The firmware's tasks for now: sense → follow → actuate → telemetry, each a small adapter
// between the executive and one piece of work. They share data only through CycleState.
#include "ringlet/behaviour/waypoint_mission.hpp"
#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/cycle_state.hpp"
#include "ringlet/firmware/telemetry.hpp"
#include "ringlet/hal/robot.hpp"

namespace ringlet::firmware {

/// HAL sensors → CycleState. On the simulated robot this is also what advances the world.
class SenseTask final : public executive::Task {
 public:
  SenseTask(hal::Sensors& sensors, CycleState& state) noexcept : sensors_(sensors), state_(state) {}
  void run(const executive::TaskContext& ctx) noexcept override;

 private:
  hal::Sensors& sensors_;
  CycleState& state_;
};

/// The waypoint follower: pose → u = (kappa, v) through the mission's goal sequence. Without a
/// valid pose it commands a stop rather than steering blind.
class FollowTask final : public executive::Task {
 public:
  FollowTask(behaviour::WaypointMission& mission, CycleState& state) noexcept : mission_(mission), state_(state) {}
  void run(const executive::TaskContext& ctx) noexcept override;

 private:
  behaviour::WaypointMission& mission_;
  CycleState& state_;
};

/// CycleState command → HAL actuators.
class ActuateTask final : public executive::Task {
 public:
  ActuateTask(hal::Actuators& actuators, CycleState& state) noexcept : actuators_(actuators), state_(state) {}
  void run(const executive::TaskContext& ctx) noexcept override;

 private:
  hal::Actuators& actuators_;
  CycleState& state_;
};

/// Records the run (trajectory every `every_frames`, collision events, goal times) and ends the
/// run once the mission is complete.
class TelemetryTask final : public executive::Task {
 public:
  TelemetryTask(Telemetry& telemetry, const behaviour::WaypointMission& mission, const CycleState& state,
                int every_frames) noexcept
      : telemetry_(telemetry), mission_(mission), state_(state), every_(static_cast<std::uint64_t>(every_frames)) {}
  void run(const executive::TaskContext& ctx) noexcept override;

 private:
  Telemetry& telemetry_;
  const behaviour::WaypointMission& mission_;
  const CycleState& state_;
  std::uint64_t every_;
  bool was_colliding_ = false;
};

}  // namespace ringlet::firmware
