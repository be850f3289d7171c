#pragma once
// What the firmware offers a task when it builds one: the robot's HAL parts, the whiteboard, the
// LLFSM schedule, the run's record and the configuration. A task takes what it needs in its
// make() and keeps references; everything here outlives every task.
#include <memory>

#include "ringlet/behaviour/llfsm/schedule.hpp"
#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/config.hpp"
#include "ringlet/firmware/experience_log.hpp"
#include "ringlet/firmware/telemetry.hpp"
#include "ringlet/hal/robot.hpp"
#include "ringlet/remote/inbox.hpp"
#include "ringlet/whiteboard/message_log.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::executive {
class Executive;
}

namespace ringlet::firmware {

struct TaskServices {
  const FirmwareConfig& config;
  hal::Robot& robot;
  hal::Camera* camera;  // the camera the configuration chose (the robot's or an OpenCV one), or null
  wb::Whiteboard& board;
  behaviour::llfsm::Schedule& schedule;
  Telemetry& telemetry;
  /// The executive is built after its tasks; this points at it before the first frame.
  const executive::Executive* const& executive;
  /// --wb-log: told the frame before each dispatch (null when not logging).
  wb::MessageLogger* message_log;
  /// [remote] accept: the remote writes the bridge accepted, delivered by the whiteboard task before
  /// its dispatch (null when nothing remote may write).
  remote::Inbox* remote_inbox = nullptr;
  /// The experiences the planner records ([planner] record, learn_online); written after the run.
  ExperienceLog* experiences = nullptr;
};

}  // namespace ringlet::firmware
