#pragma once
// A ball detector that a backend has of its own, without a camera: the simulator's idealised one
// (it reports where the world's ball really is). A real board has none; there vision finds the
// ball in camera frames. The ball sensor task reads it when the task table runs that task.
#include "ringlet/hal/geometry.hpp"
#include "ringlet/hal/time.hpp"

namespace ringlet::hal {

struct BallSighting {
  Nanos stamp{0};
  bool seen = false;
  RobotPoint at{};  // robot frame, m (valid when seen)
};

class BallSensor {
 public:
  virtual ~BallSensor() = default;
  /// Fills `out` with the sighting at the time of the last Sensors::read(); never advances a
  /// simulated world. Returns false when the detector could not be read.
  virtual bool read(BallSighting& out) noexcept = 0;
};

}  // namespace ringlet::hal
