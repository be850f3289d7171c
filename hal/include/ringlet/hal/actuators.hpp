#pragma once
// What the controller commands: u = (kappa, v) of eq. (17) and the head's yaw/pitch.
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

}  // namespace ringlet::hal
