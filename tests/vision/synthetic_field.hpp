#pragma once
// Synthetic camera frames for the vision tests and benchmarks: every pixel's viewing ray (from
// hal::camera_geometry) is traced against a flat green field with white lines, rings and an
// orange ball; above the horizon is a grey wall. Deterministic, optional per-pixel noise.
#include <cstdint>
#include <optional>
#include <vector>

#include "ringlet/hal/camera.hpp"
#include "ringlet/hal/camera_geometry.hpp"

namespace ringlet::vision::testing {

struct Bgr {
  std::uint8_t b, g, r;
};

inline constexpr Bgr kGreen{40, 140, 40};
inline constexpr Bgr kWhite{235, 235, 235};
inline constexpr Bgr kOrange{0, 120, 255};
inline constexpr Bgr kWall{130, 120, 110};
inline constexpr Bgr kBallBlack{30, 30, 30};

struct GroundSegment {
  hal::RobotPoint a, b;
  double width = 0.05;
};
struct GroundRing {
  hal::RobotPoint centre;
  double radius = 0.75;
  double width = 0.05;
};
/// A white rectangle on the ground (a robot's feet, a white blob).
struct GroundBox {
  hal::RobotPoint min, max;
};

struct Scene {
  std::vector<GroundSegment> lines;
  std::vector<GroundRing> rings;
  std::vector<GroundBox> blobs;
  std::optional<hal::RobotPoint> ball;
  double ball_radius = 0.05;
  bool ball_black_white = false;  // the SPL ball: white with 12 black pentagons (else orange)
  int noise = 0;  // ± this per channel, hashed from the pixel position
};

struct Frame {
  std::vector<std::uint8_t> bytes;
  hal::FrameView view;
};

/// The standard test camera: NAO intrinsics, default mount.
struct Camera {
  hal::CameraIntrinsics k = hal::CameraIntrinsics::nao();
  hal::CameraMount mount{};
  hal::HeadJoints head{0.0, 0.35};
  hal::BodyTilt body{};  // the torso's tilt (upright unless a test leans it)
  [[nodiscard]] hal::CameraPosture posture() const { return {body, head}; }
  [[nodiscard]] hal::CameraPose pose() const { return hal::CameraPose::from_body(mount, body, head); }
};

[[nodiscard]] Frame render(const Scene& scene, const Camera& cam, hal::PixelFormat format, std::uint64_t sequence = 0);

/// A typical view of a field: the halfway line, a touch line, the centre circle and the ball.
[[nodiscard]] Scene field_scene();

/// field_scene() with the black-and-white ball and a white blob: candidates for both HOG
/// classifiers (the ball's and the robots').
[[nodiscard]] Scene classifier_scene();

}  // namespace ringlet::vision::testing
