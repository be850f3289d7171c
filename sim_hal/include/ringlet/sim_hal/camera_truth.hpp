#pragma once
// Ground truth of one simulated camera frame: what of every painted line, ring and the ball is
// really visible in the picture (inside the image, below the horizon, not hidden by an obstacle
// or the ball). Sized when the renderer is built; filling it never allocates.
#include <cstddef>
#include <vector>

#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/hal/geometry.hpp"
#include "ringlet/hal/sensors.hpp"

namespace ringlet::sim_hal {

/// One visible stretch of a straight marking: consecutive ground samples (about 1 cm apart
/// along the line's middle) that are all visible. End points are the first and last such sample.
struct LineRunTruth {
  std::size_t marking = 0;  // index into World::markings
  hal::Pixel image_a{};
  hal::Pixel image_b{};
  hal::RobotPoint ground_a{};  // robot frame, on the ground
  hal::RobotPoint ground_b{};
};

/// A ring marking (centre circle) sampled the same way; only whether and how much is visible.
struct RingTruth {
  std::size_t ring = 0;           // index into World::rings
  bool visible = false;           // at least one sample visible
  double visible_fraction = 0.0;  // share of its samples visible
};

struct BallTruth {
  bool present = false;           // the world has a ball
  bool visible = false;           // at least one pixel of the picture shows it
  hal::RobotPoint position{};     // centre, robot frame (on the ground under the centre)
  bool in_front = false;          // the centre is in front of the camera (image_* are valid)
  hal::Pixel image_centre{};      // projection of the ball's centre (may lie outside the image)
  double image_radius = 0.0;      // pixels, fx · radius / depth
  double visible_fraction = 0.0;  // of the ball's pixels inside the image, the share not occluded
};

struct FrameTruth {
  hal::Pose2 pose{};        // true robot pose at capture
  hal::HeadJoints head{};   // head joints at capture
  hal::BodyTilt body{};     // torso tilt at capture (the camera follows the whole chain)
  std::vector<LineRunTruth> lines;  // in marking order, runs along each marking from end a to b
  bool lines_truncated = false;     // more runs than the capacity reserved; the rest were dropped
  std::vector<RingTruth> rings;     // one per World::rings entry
  BallTruth ball{};
};

}  // namespace ringlet::sim_hal
