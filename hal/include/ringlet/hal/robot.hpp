#pragma once
// The robot as the controller sees it, whatever drives it (real board, simulator, replay):
// sensors in, actuators out, a safe state every backend must honour.
#include <string_view>

#include "ringlet/hal/actuators.hpp"
#include "ringlet/hal/camera.hpp"
#include "ringlet/hal/sensors.hpp"

namespace ringlet::hal {

class Sensors {
 public:
  virtual ~Sensors() = default;
  /// Fills `out` with this cycle's readings. Called once per executive frame by the sense task;
  /// a lockstep simulator advances its world by exactly one period here. Returns false when the
  /// hardware could not be read (the frame's readings are then stale and marked invalid).
  virtual bool read(SensorFrame& out) noexcept = 0;
};

class Actuators {
 public:
  virtual ~Actuators() = default;
  /// Applies a command. Ignored while the safe state is latched.
  virtual void write(const ActuatorCommand& cmd) noexcept = 0;
  /// Motors stopped, head held where it is. Latched until the process ends: a controller that
  /// needed the safe state is not trusted to drive again. Safe to call from any thread (the
  /// watchdog and signal path call it), any number of times.
  virtual void enter_safe_state() noexcept = 0;
  [[nodiscard]] virtual bool in_safe_state() const noexcept = 0;
};

/// One backend: everything a firmware build talks to. `camera` may be null (no camera yet).
class Robot {
 public:
  virtual ~Robot() = default;
  [[nodiscard]] virtual std::string_view backend_name() const noexcept = 0;
  virtual Sensors& sensors() noexcept = 0;
  virtual Actuators& actuators() noexcept = 0;
  virtual Camera* camera() noexcept = 0;
};

}  // namespace ringlet::hal
