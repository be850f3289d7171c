#pragma once
// What the controller commands: u = (kappa, v) of eq. (17) and the head's yaw/pitch, and the
// interface of whatever carries it out.
namespace ringlet::hal {

struct DriveCommand {
  double curvature = 0.0;  // kappa, 1/m (positive turns clockwise, see geometry.hpp)
  double velocity = 0.0;   // v, m/s
};

/// Where the head should point (radians, as hal::HeadJoints). Not wb::HeadCommand: that is the
/// whiteboard message the behaviours post; the firmware's actuate task copies it into this.
struct HeadTarget {
  double yaw = 0.0;
  double pitch = 0.0;
};

struct ActuatorCommand {
  DriveCommand drive{};
  HeadTarget head{};
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

}  // namespace ringlet::hal
