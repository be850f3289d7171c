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

/// A box in the image, pixel edges: the pixels u0 <= u < u1, v0 <= v < v1 (may extend past the
/// image for a projection). Empty when u1 <= u0.
struct ImageBox {
  double u0 = 0.0, v0 = 0.0, u1 = 0.0, v1 = 0.0;
  [[nodiscard]] bool empty() const noexcept { return !(u1 > u0 && v1 > v0); }
};

struct BallTruth {
  bool present = false;           // the world has this ball
  bool visible = false;           // at least one pixel of the picture shows it
  hal::RobotPoint position{};     // centre, robot frame (on the ground under the centre)
  bool in_front = false;          // the centre is in front of the camera (image_* are valid)
  hal::Pixel image_centre{};      // projection of the ball's centre (may lie outside the image)
  double image_radius = 0.0;      // pixels, fx · radius / depth
  double visible_fraction = 0.0;  // of the ball's pixels inside the image, the share not occluded
  double distance = 0.0;          // m, on the ground from the robot's centre to under the ball's centre
  double bearing = 0.0;           // rad, of that point (robot frame, left positive)
  ImageBox pixels{};              // the pixels its silhouette covers inside the image, hidden or not
  ImageBox visible_pixels{};      // the pixels showing it
  double in_image_fraction = 0.0; // share of its projected disc inside the image (cut by an edge: < 1)
};

/// A robot (a `circle` of kind robot): where it stands and where it is in the picture.
struct RobotTruth {
  std::size_t circle = 0;         // index into World::circles
  hal::RobotPoint foot{};         // where it stands (its axis on the ground), robot frame
  double distance = 0.0;          // m, to that point
  double bearing = 0.0;           // rad, of that point (left positive)
  double heading = 0.0;           // rad, where it faces, world frame (geometry.hpp convention)
  int team = 0;                   // jersey: 0 blue, 1 red, 2 yellow, 3 black (src/camera_shading.hpp)
  bool in_front = false;          // its foot point is in front of the camera
  ImageBox box{};                 // the projection of its whole body (may extend past the image)
  ImageBox pixels{};              // the pixels its silhouette covers inside the image, hidden or not
  ImageBox visible_pixels{};      // the pixels showing it
  bool visible = false;           // at least one pixel shows it
  double visible_fraction = 0.0;  // of its silhouette's pixels inside the image, the share shown
};

struct FrameTruth {
  hal::Pose2 pose{};        // true robot pose at capture
  hal::HeadJoints head{};   // head joints at capture
  hal::BodyTilt body{};     // torso tilt at capture (the camera follows the whole chain)
  std::vector<LineRunTruth> lines;  // in marking order, runs along each marking from end a to b
  bool lines_truncated = false;     // more runs than the capacity reserved; the rest were dropped
  std::vector<RingTruth> rings;     // one per World::rings entry
  BallTruth ball{};                 // World::ball (kept for the first evaluation's readers)
  std::vector<BallTruth> balls;     // World::ball (if any) first, then World::extra_balls
  std::vector<RobotTruth> robots;   // every robot circle, in World::circles order
};

}  // namespace ringlet::sim_hal
