#pragma once
// The simulated head camera's picture: a ray per pixel through hal/camera_geometry.hpp's pinhole
// model, against the world's obstacles (cylinders, or NAO-shaped robots), the balls and the
// painted, lit carpet, in the world's CameraLook (camera_look.hpp); plus the frame's ground truth
// (what of every line, ring, ball and robot is really visible).
// Deterministic (integer-hash noise only, no <random> distributions) and allocation-free per
// frame: every buffer is sized in the constructor.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/hal/geometry.hpp"
#include "ringlet/sim_hal/camera_truth.hpp"
#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal {

/// The camera being simulated: intrinsics (image size included) and where it sits on the head.
struct CameraSpec {
  hal::CameraIntrinsics intrinsics = hal::CameraIntrinsics::nao();
  hal::CameraMount mount{};
};

/// What each pixel shows: the renderer's exact segmentation, for tests and datasets.
enum class PixelLabel : std::uint8_t {
  kBackground = 0,  // nothing hit: above the horizon
  kFloor = 1,       // ground outside the carpet (beyond the bounds)
  kCarpet = 2,
  kMarking = 3,     // painted line or ring
  kBall = 4,
  kRobot = 5,
  kPost = 6,
  kObstacle = 7,
};

class CameraRenderer {
 public:
  /// Copies the world and precomputes a grid of the markings. `seed` varies the carpet texture
  /// and the background; the same seed always gives the same pictures.
  CameraRenderer(World world, const CameraSpec& spec, std::uint64_t seed);

  /// Renders the view from the true robot pose `pose` with the torso tilted and the head turned as
  /// `posture` says (the camera of hal::CameraPose::from_posture) into bgr(), and the ground truth
  /// into truth(). Never allocates. Each call is the next frame: the look's auto-exposure drift and
  /// the sensor noise follow the frame count.
  void render(const hal::Pose2& pose, const hal::CameraPosture& posture) noexcept;
  /// An upright torso: render(pose, {{}, head}).
  void render(const hal::Pose2& pose, const hal::HeadJoints& head) noexcept {
    render(pose, hal::CameraPosture{hal::BodyTilt{}, head});
  }

  /// Frames rendered so far.
  [[nodiscard]] std::uint64_t frames_rendered() const noexcept { return frame_; }

  /// BGR8, rows top to bottom, stride = 3 · width, no padding.
  [[nodiscard]] std::span<const std::uint8_t> bgr() const noexcept { return bgr_; }
  /// One PixelLabel per pixel, same layout as bgr() with stride = width.
  [[nodiscard]] std::span<const PixelLabel> labels() const noexcept { return labels_; }
  [[nodiscard]] const FrameTruth& truth() const noexcept { return truth_; }
  [[nodiscard]] const CameraSpec& spec() const noexcept { return spec_; }
  [[nodiscard]] const World& world() const noexcept { return world_; }

  /// Capacity for visible line runs: every line may be cut into pieces by each obstacle and the
  /// ball. More runs than this are dropped and FrameTruth::lines_truncated is set.
  [[nodiscard]] std::size_t line_run_capacity() const noexcept { return truth_.lines.capacity(); }

 private:
  struct Grid {
    double x0 = 0.0, y0 = 0.0, cell = 0.25;
    int nx = 0, ny = 0;
    std::vector<std::uint32_t> first;  // per cell: start in `items`, plus one end entry
    std::vector<std::uint32_t> items;  // marking index, or ring index | kRingBit
  };
  struct ScreenBox {
    int u0 = 0, u1 = -1, v0 = 0, v1 = -1;  // inclusive pixel ranges; empty when u1 < u0
  };

  /// Per object (circles, then balls), this frame: rays that meet it whatever is in front
  /// (`hits`, and their pixel bounds) and pixels where it is the nearest thing (`shown`).
  struct ObjectStats {
    std::uint64_t hits = 0, shown = 0;
    int hit_u0 = 0, hit_u1 = -1, hit_v0 = 0, hit_v1 = -1;
    int shown_u0 = 0, shown_u1 = -1, shown_v0 = 0, shown_v1 = -1;
  };
  /// A robot's NAO pose: turned to `sin_h`/`cos_h`, scaled by `scale` (= height / 0.574 m).
  struct RobotFrame {
    double sin_h = 0.0, cos_h = 1.0, heading = 0.0, scale = 1.0;
    std::uint8_t team = 0;
  };

  void build_grid();
  void setup_objects();
  void render_pixels() noexcept;
  void post_process() noexcept;  // camera_post.cpp: motion blur, sensor noise
  void compute_camera_gains() noexcept;
  void compute_obstacle_boxes() noexcept;
  void compute_truth() noexcept;  // camera_truth.cpp
  void compute_object_truth() noexcept;  // camera_truth.cpp
  [[nodiscard]] bool sample_visible(const hal::Vec3& ground, hal::Pixel& px) const noexcept;
  /// Nearest hit t of the ray o + t·d with object i (circle, or ball i − circles), or +inf.
  [[nodiscard]] double hit_object(std::size_t i, const hal::Vec3& o, const hal::Vec3& d) const noexcept;
  [[nodiscard]] bool nao_robot(std::size_t circle) const noexcept;

  World world_;
  CameraSpec spec_;
  std::uint32_t seed_;
  Grid grid_;
  std::vector<std::uint8_t> bgr_;
  std::vector<PixelLabel> labels_;
  std::vector<Ball> balls_;              // World::ball (if any), then World::extra_balls
  std::vector<RobotFrame> robot_frames_;  // one per circle (used for robots)
  std::vector<std::array<hal::Vec3, 3>> ball_axes_;  // each ball's pattern orientation
  std::vector<ObjectStats> stats_;       // one per circle, then per ball
  std::vector<std::uint8_t> line_buffer_;  // one row or column of pixels, for the blur
  std::vector<ScreenBox> boxes_;         // one per circle, then per ball
  std::vector<std::uint32_t> row_active_;  // obstacles whose box covers the current row
  FrameTruth truth_;
  // This frame's camera in the world frame.
  hal::Pose2 pose_{};
  hal::Vec3 origin_{};
  std::array<hal::Vec3, 3> axes_{};
  std::uint64_t frame_ = 0;              // frames rendered
  std::array<double, 3> gain_{1.0, 1.0, 1.0};  // this frame's camera gains, B G R
};

}  // namespace ringlet::sim_hal
