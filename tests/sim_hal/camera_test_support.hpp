#pragma once
// Helpers for the camera tests: a plain field world built in code, and where a robot-frame point
// lands in the picture (through hal/camera_geometry.hpp, the model the renderer must follow).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>

#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/sim_hal/camera_renderer.hpp"

namespace ringlet::sim_hal::test {

/// A 10 m x 8 m carpet centred on the origin, no markings, no obstacles, no sun stripes.
inline World open_field() {
  World world;
  world.name = "open field";
  world.min = {-5.0, -4.0};
  world.max = {5.0, 4.0};
  world.start = {0.0, 0.0, 0.0};
  return world;
}

/// A pose whose robot frame is the world frame: at the origin, facing +x (east).
inline hal::Pose2 facing_east() { return {0.0, 0.0, std::numbers::pi / 2.0}; }

struct PixelIndex {
  int u = 0;
  int v = 0;
};

/// The pixel that shows robot-frame point p (which must be in front of the camera).
inline PixelIndex pixel_of(const CameraSpec& spec, const hal::HeadJoints& head, const hal::Vec3& p) {
  const auto px = hal::project(spec.intrinsics, hal::CameraPose::from_head(spec.mount, head), p);
  return {static_cast<int>(std::floor(px->u)), static_cast<int>(std::floor(px->v))};
}

struct Bgr {
  int b = 0, g = 0, r = 0;
};

inline Bgr bgr_at(const CameraRenderer& r, PixelIndex p) {
  const auto i = (static_cast<std::size_t>(p.v) * static_cast<std::size_t>(r.spec().intrinsics.width) +
                  static_cast<std::size_t>(p.u)) * 3U;
  return {r.bgr()[i], r.bgr()[i + 1], r.bgr()[i + 2]};
}

inline PixelLabel label_at(const CameraRenderer& r, PixelIndex p) {
  return r.labels()[static_cast<std::size_t>(p.v) * static_cast<std::size_t>(r.spec().intrinsics.width) +
                    static_cast<std::size_t>(p.u)];
}

}  // namespace ringlet::sim_hal::test
