// The render thread hand-over of the simulated camera. One job at a time: a capture hands over a
// slot and the pose; the next tick waits for "done" and delivers that slot.
#include "ringlet/sim_hal/sim_camera.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "number_text.hpp"
#include "ringlet/hal/yuv.hpp"

namespace ringlet::sim_hal {
namespace {

std::size_t frame_bytes(const SimCameraConfig& c) noexcept {
  const std::size_t per_pixel = c.format == hal::PixelFormat::kYuyv ? 2U : 3U;
  return static_cast<std::size_t>(c.intrinsics.width) * static_cast<std::size_t>(c.intrinsics.height) * per_pixel;
}

[[noreturn]] void reject(const std::string& field, const std::string& rule, const std::string& got) {
  throw std::invalid_argument("sim.camera." + field + " must be " + rule + ", got " + got);
}

}  // namespace

void validate(const SimCameraConfig& c) {
  if (c.intrinsics.width < 2 || c.intrinsics.width > 4096) reject("width", "in 2..4096", std::to_string(c.intrinsics.width));
  if (c.intrinsics.height < 1 || c.intrinsics.height > 4096) {
    reject("height", "in 1..4096", std::to_string(c.intrinsics.height));
  }
  if (c.format == hal::PixelFormat::kYuyv && c.intrinsics.width % 2 != 0) {
    reject("width", "even for yuyv (two pixels share U and V)", std::to_string(c.intrinsics.width));
  }
  if (c.format != hal::PixelFormat::kYuyv && c.format != hal::PixelFormat::kBgr8) reject("format", "yuyv or bgr", "gray");
  const auto positive = [](const char* field, double v) {
    if (!(std::isfinite(v) && v > 0.0)) reject(field, "finite and > 0", detail::format_number(v));
  };
  positive("fx", c.intrinsics.fx);
  positive("fy", c.intrinsics.fy);
  if (!std::isfinite(c.intrinsics.cx) || !std::isfinite(c.intrinsics.cy)) reject("cx/cy", "finite", "a non-finite value");
  positive("pivot_height", c.mount.pivot_height);
  if (!std::isfinite(c.mount.forward) || !std::isfinite(c.mount.up)) reject("mount", "finite", "a non-finite offset");
  if (c.every_n_frames < 1 || c.every_n_frames > 1000) {
    reject("every_n_frames", "in 1..1000", std::to_string(c.every_n_frames));
  }
}

SimCamera::SimCamera(const World& world, const SimCameraConfig& config, std::uint64_t seed)
    : config_(config),
      renderer_((validate(config), world), CameraSpec{config.intrinsics, config.mount}, seed),
      stride_(config.intrinsics.width * (config.format == hal::PixelFormat::kYuyv ? 2 : 3)) {
  for (Slot& slot : slots_) {
    slot.pixels.resize(frame_bytes(config_));
    slot.truth.lines.reserve(renderer_.line_run_capacity());
    slot.truth.rings.reserve(world.rings.size());
    slot.truth.balls.reserve(renderer_.truth().balls.capacity());
    slot.truth.robots.reserve(renderer_.truth().robots.capacity());
  }
  thread_ = std::thread([this] { render_loop(); });
}

SimCamera::~SimCamera() {
  {
    const std::lock_guard lock(job_mutex_);
    stop_ = true;
  }
  job_cv_.notify_all();
  thread_.join();
}

int SimCamera::free_slot() const noexcept {
  for (int i = 0; i < static_cast<int>(slots_.size()); ++i) {
    if (i != latest_ && i != held_) return i;
  }
  return 0;  // unreachable with three slots
}

void SimCamera::on_step(std::uint64_t step, hal::Nanos time, const hal::Pose2& pose,
                        const hal::CameraPosture& posture) noexcept {
  if (step % static_cast<std::uint64_t>(config_.every_n_frames) != 0) return;
  const std::lock_guard slots_lock(slots_mutex_);
  if (in_flight_ >= 0) {
    // Deliver the previous capture: one camera period of latency, waiting if it is not done.
    std::unique_lock lock(job_mutex_);
    if (!job_done_) {
      ++waits_;
      job_cv_.wait(lock, [this] { return job_done_; });
    }
    job_done_ = false;
    latest_ = in_flight_;
    in_flight_ = -1;
  }
  const int slot = free_slot();
  Slot& s = slots_[static_cast<std::size_t>(slot)];
  s.capture_time = time;
  s.sequence = ++captures_;
  in_flight_ = slot;
  {
    const std::lock_guard lock(job_mutex_);
    job_ = Job{slot, pose, posture};
    job_pending_ = true;
  }
  job_cv_.notify_all();
}

void SimCamera::render_loop() noexcept {
  for (;;) {
    Job job;
    {
      std::unique_lock lock(job_mutex_);
      job_cv_.wait(lock, [this] { return job_pending_ || stop_; });
      if (stop_) return;
      job = job_;
      job_pending_ = false;
    }
    renderer_.render(job.pose, job.posture);
    Slot& s = slots_[static_cast<std::size_t>(job.slot)];
    const auto bgr = renderer_.bgr();
    if (config_.format == hal::PixelFormat::kYuyv) {
      hal::bgr_to_yuyv(bgr, config_.intrinsics.width, config_.intrinsics.height, s.pixels);
    } else {
      std::copy(bgr.begin(), bgr.end(), s.pixels.begin());
    }
    s.truth = renderer_.truth();  // capacity was reserved: no allocation
    {
      const std::lock_guard lock(job_mutex_);
      job_done_ = true;
    }
    job_cv_.notify_all();
  }
}

bool SimCamera::grab_latest(hal::FrameView& out) noexcept {
  const std::lock_guard lock(slots_mutex_);
  if (latest_ < 0) return false;
  held_ = latest_;
  const Slot& s = slots_[static_cast<std::size_t>(latest_)];
  out.capture_time = s.capture_time;
  out.sequence = s.sequence;
  out.format = config_.format;
  out.width = config_.intrinsics.width;
  out.height = config_.intrinsics.height;
  out.stride = stride_;
  out.data = s.pixels.data();
  return true;
}

const FrameTruth* SimCamera::latest_truth() const noexcept {
  const std::lock_guard lock(slots_mutex_);
  return latest_ < 0 ? nullptr : &slots_[static_cast<std::size_t>(latest_)].truth;
}

}  // namespace ringlet::sim_hal
