// The camera model as rotations and transforms: the torso's tilt is Ry(pitch)·Rx(roll) about the
// ground point under the robot, the head's rotation on it is Rz(yaw)·Ry(pitch), the
// camera's axes are a fixed permutation of the head's, and a CameraPose stores the columns of the
// camera→robot rotation (its `axes`) with the camera's position. Eigen does the products; the
// types are fixed-size (3×3, 3-vectors) and live on the stack, so nothing here allocates.
#include "ringlet/hal/camera_geometry.hpp"

#include <Eigen/Core>
#include <cmath>

namespace ringlet::hal {
namespace {

Eigen::Vector3d to_eigen(const Vec3& v) noexcept { return {v.x, v.y, v.z}; }
Vec3 to_vec3(const Eigen::Vector3d& v) noexcept { return {v.x(), v.y(), v.z()}; }

// The elementary rotations written out rather than built through AngleAxis or a quaternion: their
// entries are exactly ±sin, ±cos, 0 and 1, so the products below stay exact where they can.
Eigen::Matrix3d rotation_z(double angle) noexcept {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d r;
  r << c, -s, 0.0,  //
      s, c, 0.0,    //
      0.0, 0.0, 1.0;
  return r;
}

Eigen::Matrix3d rotation_y(double angle) noexcept {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d r;
  r << c, 0.0, s,  //
      0.0, 1.0, 0.0,  //
      -s, 0.0, c;
  return r;
}

Eigen::Matrix3d rotation_x(double angle) noexcept {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d r;
  r << 1.0, 0.0, 0.0,  //
      0.0, c, -s,  //
      0.0, s, c;
  return r;
}

// Camera axes in the head frame, as columns: right = −head y, down = −head z, forward = head x.
Eigen::Matrix3d camera_in_head() noexcept {
  Eigen::Matrix3d p;
  p << 0.0, 0.0, 1.0,  //
      -1.0, 0.0, 0.0,  //
      0.0, -1.0, 0.0;
  return p;
}

// The camera→robot rotation: its columns are the pose's axes.
Eigen::Matrix3d camera_to_robot(const CameraPose& pose) noexcept {
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i) r.col(i) = to_eigen(pose.axes[static_cast<std::size_t>(i)]);
  return r;
}

}  // namespace

CameraIntrinsics CameraIntrinsics::from_fov(int width, int height, double hfov_deg, double vfov_deg) noexcept {
  CameraIntrinsics k;
  k.width = width;
  k.height = height;
  k.cx = width / 2.0;
  k.cy = height / 2.0;
  k.fx = k.cx / std::tan(deg_to_rad(hfov_deg) / 2.0);
  k.fy = k.cy / std::tan(deg_to_rad(vfov_deg) / 2.0);
  return k;
}

CameraPose CameraPose::from_body(const CameraMount& mount, const BodyTilt& body, const HeadJoints& head) noexcept {
  // Head axes in the torso frame: Rz(yaw) · Ry(pitch); a positive rotation about y tips the x axis
  // down, which is what a positive (downward) pitch does, and a forward-leaning torso likewise.
  const Eigen::Matrix3d head_to_torso = rotation_z(head.yaw) * rotation_y(head.pitch);
  const Eigen::Vector3d pivot{0.0, 0.0, mount.pivot_height};
  const Eigen::Vector3d camera_in_head_frame{mount.forward, 0.0, mount.up};
  Eigen::Matrix3d head_to_robot = head_to_torso;
  Eigen::Vector3d position = pivot + head_to_torso * camera_in_head_frame;
  // An upright torso is the identity: skipped rather than multiplied by, so that the upright pose
  // is bit for bit what it was before the torso entered the chain (golden runs depend on it).
  if (body.pitch != 0.0 || body.roll != 0.0) {
    const Eigen::Matrix3d torso_to_robot = rotation_y(body.pitch) * rotation_x(body.roll);
    head_to_robot = torso_to_robot * head_to_torso;
    position = torso_to_robot * position;  // the torso turns about the robot frame's origin
  }
  // A camera mounted pitched turns about its own x axis (parallel to the pitch joint's), in place;
  // 0 is skipped like the upright torso, so the nominal mount's poses stay bit for bit.
  Eigen::Matrix3d mount_to_robot = head_to_robot;
  if (mount.pitch != 0.0) mount_to_robot = head_to_robot * rotation_y(mount.pitch);
  const Eigen::Matrix3d axes = mount_to_robot * camera_in_head();
  CameraPose pose;
  pose.position = to_vec3(position);
  for (int i = 0; i < 3; ++i) pose.axes[static_cast<std::size_t>(i)] = to_vec3(axes.col(i));
  return pose;
}

Vec3 CameraPose::to_camera(const Vec3& robot) const noexcept {
  return to_vec3(camera_to_robot(*this).transpose() * (to_eigen(robot) - to_eigen(position)));
}

Vec3 CameraPose::to_robot_direction(const Vec3& camera) const noexcept {
  return to_vec3(camera_to_robot(*this) * to_eigen(camera));
}

std::optional<Pixel> project(const CameraIntrinsics& k, const CameraPose& pose, const Vec3& robot) noexcept {
  const Vec3 c = pose.to_camera(robot);
  if (!(c.z > 1e-9)) return std::nullopt;
  return Pixel{k.fx * c.x / c.z + k.cx, k.fy * c.y / c.z + k.cy};
}

Vec3 pixel_ray(const CameraIntrinsics& k, const CameraPose& pose, const Pixel& px) noexcept {
  return pose.to_robot_direction({(px.u - k.cx) / k.fx, (px.v - k.cy) / k.fy, 1.0});
}

std::optional<RobotPoint> pixel_to_ground(const CameraIntrinsics& k, const CameraPose& pose, const Pixel& px) noexcept {
  const Eigen::Vector3d ray = to_eigen(pixel_ray(k, pose, px));
  if (!(ray.z() < -1e-12)) return std::nullopt;  // level or upwards: never meets the ground
  const Eigen::Vector3d origin = to_eigen(pose.position);
  const Eigen::Vector3d ground = origin + (-origin.z() / ray.z()) * ray;
  return RobotPoint{ground.x(), ground.y()};
}

}  // namespace ringlet::hal
