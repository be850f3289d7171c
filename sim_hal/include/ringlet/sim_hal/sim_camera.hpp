#pragma once
// The simulated head camera as a hal::Camera. Rendering a frame takes milliseconds, so it never
// runs inside a real-time task: a render thread owned by the camera does it. The lockstep contract
// keeps runs bit-identical whatever the host's speed:
//   - camera tick k is the SimRobot::read() that ends step k·every_n_frames; the true pose, torso
//     tilt and head joints of that instant are handed to the render thread (a capture);
//   - the frame captured at tick k becomes the latest frame at tick k+1 (one camera period of
//     latency, like a real camera's exposure and readout); if the render thread has not finished
//     it by then, that read() waits for it;
//   - grab_latest() returns the newest delivered frame, capture_time = the sim time of its
//     capture, sequence = k.
// on_step() and grab_latest() are meant for the executive's thread; the pixels a grab returns
// stay valid until the next grab (three slots: one delivered, one held by the reader, one being
// rendered).
#include <array>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "ringlet/hal/camera.hpp"
#include "ringlet/sim_hal/camera_renderer.hpp"

namespace ringlet::sim_hal {

struct SimCameraConfig {
  bool enabled = false;
  hal::CameraIntrinsics intrinsics = hal::CameraIntrinsics::nao();  // 640×480, 57°×44°
  hal::CameraMount mount{};
  hal::PixelFormat format = hal::PixelFormat::kYuyv;  // kYuyv or kBgr8
  int every_n_frames = 3;                              // 30 fps at a 10 ms period
};

/// Throws std::invalid_argument naming the field ("sim.camera.width must be ...").
void validate(const SimCameraConfig& config);

class SimCamera final : public hal::Camera {
 public:
  /// Starts the render thread. All buffers are allocated here.
  SimCamera(const World& world, const SimCameraConfig& config, std::uint64_t seed);
  ~SimCamera() override;  // stops and joins the render thread
  SimCamera(const SimCamera&) = delete;
  SimCamera& operator=(const SimCamera&) = delete;

  bool grab_latest(hal::FrameView& out) noexcept override;

  /// Called by SimRobot::read() after every step, with the state at the end of step `step`.
  void on_step(std::uint64_t step, hal::Nanos time, const hal::Pose2& pose, const hal::CameraPosture& posture) noexcept;

  /// Ground truth of the newest delivered frame (what grab_latest() returns now); null before the
  /// first delivery. Valid until the next on_step().
  [[nodiscard]] const FrameTruth* latest_truth() const noexcept;
  [[nodiscard]] const SimCameraConfig& config() const noexcept { return config_; }
  /// How often a camera tick had to wait for the render thread (realtime runs want this at 0).
  [[nodiscard]] std::uint64_t waits() const noexcept { return waits_; }

 private:
  struct Slot {
    std::vector<std::uint8_t> pixels;
    FrameTruth truth;
    hal::Nanos capture_time{0};
    std::uint64_t sequence = 0;
  };
  struct Job {
    int slot = -1;
    hal::Pose2 pose{};
    hal::CameraPosture posture{};
  };

  void render_loop() noexcept;
  [[nodiscard]] int free_slot() const noexcept;

  SimCameraConfig config_;
  CameraRenderer renderer_;  // used only by the render thread once it runs
  std::array<Slot, 3> slots_;
  int stride_ = 0;

  // Executive-thread state, guarded by slots_mutex_ so a grab from another thread is still safe.
  mutable std::mutex slots_mutex_;
  int latest_ = -1;
  int held_ = -1;
  int in_flight_ = -1;
  std::uint64_t captures_ = 0;
  std::uint64_t waits_ = 0;

  // Hand-over to the render thread.
  std::mutex job_mutex_;
  std::condition_variable job_cv_;
  Job job_{};
  bool job_pending_ = false;
  bool job_done_ = false;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace ringlet::sim_hal
