#pragma once
// What the firmware's own tasks keep of one frame besides the whiteboard: the raw sensor reading
// (telemetry records it) and, on the simulated robot, the ground truth that scores the run. The
// algorithms (the LLFSMs) never see this: they read and write the whiteboard only.
#include <optional>

#include "ringlet/hal/geometry.hpp"
#include "ringlet/hal/sensors.hpp"

namespace ringlet::firmware {

struct CycleState {
  hal::SensorFrame sensors{};
  bool sensors_ok = false;
  std::optional<hal::RobotPoint> true_ball;  // simulator ground truth (sim backend only)
};

}  // namespace ringlet::firmware
