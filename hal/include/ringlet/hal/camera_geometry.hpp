#pragma once
// Where the head camera looks: a pinhole camera on a pan-tilt head, shared by everything that maps
// pixels to the world and back (the simulated camera renders with it, vision projects with it).
//
// Frames (the kinematic chain, from the ground up):
//   robot  — x ahead, y left, z up; origin on the ground under the robot's centre (RobotPoint).
//            It stays level: the ground is z = 0 whatever the torso does.
//   torso  — the robot frame tilted about its origin by the body's pitch about y (positive leans
//            forward), then by its roll about the tilted x axis (positive leans to the right):
//            R_torso = Ry(pitch) · Rx(roll), hal::BodyTilt. Upright, torso = robot.
//   head   — the torso frame turned by yaw about its z (left positive), then by pitch about the
//            turned y axis (positive looks down, as hal::HeadJoints), about the pan-tilt pivot
//            `pivot_height` above the origin along the torso's z axis.
//   camera — OpenCV's: x right, y down, z along the optical axis (= head x).
// Pixels: u = fx·X/Z + cx to the right, v = fy·Y/Z + cy downwards, (0, 0) the top-left corner of
// the top-left pixel.
#include <array>
#include <optional>

#include "ringlet/hal/geometry.hpp"
#include "ringlet/hal/sensors.hpp"

namespace ringlet::hal {

struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

struct Pixel {
  double u = 0.0;
  double v = 0.0;
};

struct CameraIntrinsics {
  int width = 640;
  int height = 480;
  double fx = 0.0;
  double fy = 0.0;
  double cx = 0.0;
  double cy = 0.0;

  /// fx and fy from the two fields of view (degrees); principal point at the image centre.
  [[nodiscard]] static CameraIntrinsics from_fov(int width, int height, double hfov_deg, double vfov_deg) noexcept;
  /// The NAO's head camera: 640×480, about 57° × 44°.
  [[nodiscard]] static CameraIntrinsics nao() noexcept { return from_fov(640, 480, 57.0, 44.0); }
};

/// Where the camera sits on the head: the pan-tilt pivot's height above the ground, the camera's
/// offset from the pivot in the head frame (ahead, up), and how far it is pitched down in the
/// head as mounted (a real head's camera sits a degree or two off; `ringlet-vision --auto-pitch`
/// measures it from the field lines).
struct CameraMount {
  double pivot_height = 0.45;  // m
  double forward = 0.05;       // m
  double up = 0.06;            // m
  double pitch = 0.0;          // rad, down positive (as the head's pitch)
};

/// The NAO's head joint ranges (Aldebaran's NAO V6 joint documentation: HeadYaw ±119.5°, HeadPitch
/// −38.5° to +29.5° in its convention, where positive also looks down). Tools that take a head
/// posture from the user refuse anything outside, so a typo cannot put the camera upside down.
struct NaoHeadRange {
  static constexpr double kMaxYawDeg = 119.5;
  static constexpr double kMinPitchDeg = -38.5;  // looking up
  static constexpr double kMaxPitchDeg = 29.5;   // looking down
};

/// Everything between the ground and the camera that moves: the torso's tilt and the head joints.
/// (A constructor rather than an aggregate: `{yaw, pitch}` stays a HeadJoints wherever an overload
/// takes either, instead of being ambiguous through brace elision.)
struct CameraPosture {
  BodyTilt body{};
  HeadJoints head{};

  constexpr CameraPosture() noexcept = default;
  constexpr CameraPosture(const BodyTilt& tilt, const HeadJoints& joints) noexcept : body(tilt), head(joints) {}
};

/// The NAO's torso tilt that the tools accept from a user: a standing or walking NAO leans a few
/// degrees (1–7° measured on real photos); past about 30° forward or 20° sideways it is falling
/// and its camera is of no use for the field.
struct BodyTiltRange {
  static constexpr double kMaxPitchDeg = 30.0;
  static constexpr double kMaxRollDeg = 20.0;
};

/// The camera for one posture: its position and axes, in the robot frame. The axes are the
/// columns of the camera→robot rotation (camera_geometry.cpp composes and applies it with Eigen;
/// this header stays plain so that the layers above need no Eigen).
struct CameraPose {
  Vec3 position{};
  std::array<Vec3, 3> axes{};  // camera x (right), y (down), z (optical axis), as robot vectors

  /// The whole chain: ground → torso tilted by `body` → head joints → camera.
  [[nodiscard]] static CameraPose from_body(const CameraMount& mount, const BodyTilt& body,
                                            const HeadJoints& head) noexcept;
  [[nodiscard]] static CameraPose from_posture(const CameraMount& mount, const CameraPosture& posture) noexcept {
    return from_body(mount, posture.body, posture.head);
  }
  /// An upright torso (zero tilt): from_body(mount, {}, head), bit for bit.
  [[nodiscard]] static CameraPose from_head(const CameraMount& mount, const HeadJoints& head) noexcept {
    return from_body(mount, BodyTilt{}, head);
  }

  /// A robot-frame point in camera coordinates.
  [[nodiscard]] Vec3 to_camera(const Vec3& robot) const noexcept;
  /// A camera-frame direction as a robot-frame direction.
  [[nodiscard]] Vec3 to_robot_direction(const Vec3& camera) const noexcept;
};

/// The pixel a robot-frame point projects to; none when it lies behind (or on) the camera plane.
/// The pixel may be outside the image.
[[nodiscard]] std::optional<Pixel> project(const CameraIntrinsics& k, const CameraPose& pose, const Vec3& robot) noexcept;

/// Where the viewing ray through pixel (u, v) meets the ground (z = 0); none at or above the
/// horizon.
[[nodiscard]] std::optional<RobotPoint> pixel_to_ground(const CameraIntrinsics& k, const CameraPose& pose,
                                                        const Pixel& px) noexcept;

/// The robot-frame direction of the viewing ray through pixel (u, v) (not normalised).
[[nodiscard]] Vec3 pixel_ray(const CameraIntrinsics& k, const CameraPose& pose, const Pixel& px) noexcept;

}  // namespace ringlet::hal
