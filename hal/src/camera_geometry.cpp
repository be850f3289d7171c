#include "ringlet/hal/camera_geometry.hpp"

#include <cmath>

namespace ringlet::hal {
namespace {

Vec3 add(const Vec3& a, const Vec3& b) noexcept { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 sub(const Vec3& a, const Vec3& b) noexcept { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3 scale(double s, const Vec3& a) noexcept { return {s * a.x, s * a.y, s * a.z}; }
double dot(const Vec3& a, const Vec3& b) noexcept { return a.x * b.x + a.y * b.y + a.z * b.z; }

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

CameraPose CameraPose::from_head(const CameraMount& mount, const HeadJoints& head) noexcept {
  // Head axes in the robot frame: R = Rz(yaw) · Ry(pitch); a positive rotation about y tips the
  // x axis down, which is what a positive (downward) pitch does.
  const double cy = std::cos(head.yaw), sy = std::sin(head.yaw);
  const double cp = std::cos(head.pitch), sp = std::sin(head.pitch);
  const Vec3 head_x{cy * cp, sy * cp, -sp};
  const Vec3 head_y{-sy, cy, 0.0};
  const Vec3 head_z{cy * sp, sy * sp, cp};
  CameraPose pose;
  pose.position = add(Vec3{0.0, 0.0, mount.pivot_height}, add(scale(mount.forward, head_x), scale(mount.up, head_z)));
  pose.axes = {scale(-1.0, head_y), scale(-1.0, head_z), head_x};  // right, down, forward
  return pose;
}

Vec3 CameraPose::to_camera(const Vec3& robot) const noexcept {
  const Vec3 d = sub(robot, position);
  return {dot(d, axes[0]), dot(d, axes[1]), dot(d, axes[2])};
}

Vec3 CameraPose::to_robot_direction(const Vec3& c) const noexcept {
  return add(add(scale(c.x, axes[0]), scale(c.y, axes[1])), scale(c.z, axes[2]));
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
  const Vec3 ray = pixel_ray(k, pose, px);
  if (!(ray.z < -1e-12)) return std::nullopt;  // level or upwards: never meets the ground
  const double t = -pose.position.z / ray.z;
  return RobotPoint{pose.position.x + t * ray.x, pose.position.y + t * ray.y};
}

}  // namespace ringlet::hal
