#pragma once
// The robot as the controller sees it, whatever drives it (real board, simulator, replay):
// sensors in, actuators out, a safe state every backend must honour.
#include <string_view>

#include "ringlet/hal/actuators.hpp"
#include "ringlet/hal/ball_sensor.hpp"
#include "ringlet/hal/board_health.hpp"
#include "ringlet/hal/camera.hpp"
#include "ringlet/hal/ground_truth.hpp"
#include "ringlet/hal/sensors.hpp"

namespace ringlet::hal {

/// One backend: everything a firmware build talks to. The optional parts are null when the
/// backend has none: a camera, a ball detector of its own, and ground truth (a simulator only).
class Robot {
 public:
  virtual ~Robot() = default;
  [[nodiscard]] virtual std::string_view backend_name() const noexcept = 0;
  virtual Sensors& sensors() noexcept = 0;
  virtual Actuators& actuators() noexcept = 0;
  virtual Camera* camera() noexcept = 0;
  virtual BallSensor* ball_sensor() noexcept { return nullptr; }
  /// The link to a real board (hal/board_health.hpp), or null for a backend without one. Read by
  /// the sense task on the cycle's thread, after read().
  [[nodiscard]] virtual const BoardHealth* board_health() const noexcept { return nullptr; }
  /// What really happened, for scoring and pictures only: the firmware hands it to its report
  /// code, never to a task or a machine.
  [[nodiscard]] virtual const GroundTruth* ground_truth() const noexcept { return nullptr; }
};

}  // namespace ringlet::hal
