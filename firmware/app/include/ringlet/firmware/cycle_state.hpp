#pragma once
// What the firmware's tasks hand each other within a frame: this cycle's sensor reading and the
// command to apply. Owned by the stack, written by one task, read by the ones after it in the
// table. (The typed whiteboard replaces this struct when the LLFSMs arrive.)
#include "ringlet/hal/actuators.hpp"
#include "ringlet/hal/sensors.hpp"

namespace ringlet::firmware {

struct CycleState {
  hal::SensorFrame sensors{};
  bool sensors_ok = false;
  hal::ActuatorCommand command{};
};

}  // namespace ringlet::firmware
