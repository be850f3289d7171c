#pragma once
// The real camera backend, through OpenCV's VideoCapture: a V4L2 device on the robot (YUYV
// 640×480 at 30 fps), or, for replay on the desktop, a video file or a folder of images (PNG or
// JPEG, in name order). A capture thread owns all I/O and decoding; grab_latest() only swaps a
// buffer, so the vision task never blocks on the camera.
//
// Live devices deliver the newest frame (older ones are dropped and show as sequence gaps).
// Replays deliver every frame in order, one per grab, so an evaluation sees exactly the recorded
// frames; a grab before the next frame is decoded returns the previous one again (same sequence).
//
// Image folders: each file is read with hal::read_file (regular files, at most
// kMaxBinaryFileBytes) and its header checked by hal::probe_image (PNG or JPEG, at most
// kMaxImagePixels) before OpenCV decodes it. At start-up the files are tried in order until one
// decodes: a folder where none does, or whose first decodable image has the wrong size, is a
// CameraError then, not a silent run without frames. During the replay an undecodable file is
// skipped (the next one gets the next sequence number), counted, and reported through
// the warning sink (standard error by default): one line per file for the first few, and a summary naming the
// first when the replay ends.
#include <functional>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "ringlet/hal/camera.hpp"
#include "ringlet/hal/clock.hpp"

namespace ringlet::hal {

class CameraError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct OpenCvCameraConfig {
  std::string source;          // "/dev/video0" or "0": device; a folder: images; else a video file
  int width = 640;             // every frame is delivered at this size (replays must match it)
  int height = 480;
  double fps = 30.0;           // requested from devices
  PixelFormat format = PixelFormat::kYuyv;  // what grab_latest() hands out: kYuyv or kBgr8
};

/// Where replay warnings go (undecodable files): called from the capture thread with
/// "<source>: <what>". Empty: one line each on standard error, "ringlet camera: warning: ...".
using CameraWarningSink = std::function<void(const std::string&)>;

class OpenCvCamera final : public Camera {
 public:
  /// Opens the source and starts the capture thread. Throws CameraError naming the source and
  /// what is wrong (cannot open, no images in the folder, none decodes, frame size differs, ...).
  /// `clock` stamps capture times and must outlive the camera.
  OpenCvCamera(const OpenCvCameraConfig& config, const Clock& clock, CameraWarningSink warn = {});
  ~OpenCvCamera() override;
  OpenCvCamera(const OpenCvCamera&) = delete;
  OpenCvCamera& operator=(const OpenCvCamera&) = delete;

  bool grab_latest(FrameView& out) noexcept override;

  /// Replays: true once every frame was delivered. Live devices: never.
  [[nodiscard]] bool finished() const noexcept;
  /// The first error the capture thread met (a replay frame of the wrong size, a device that
  /// stopped delivering), or empty.
  [[nodiscard]] std::string error() const;
  /// Image-folder replays: files skipped so far because they could not be read or decoded.
  [[nodiscard]] std::size_t undecodable_files() const noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ringlet::hal
