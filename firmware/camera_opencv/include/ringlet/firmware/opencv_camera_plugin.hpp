#pragma once
// The OpenCV camera plugin's interface: what the `ringlet` binary and the module
// ringlet_camera_opencv.so (firmware/camera_opencv/CMakeLists.txt) agree on.
//
// Why a plugin: OpenCV and the ~240 libraries it loads (codecs, GDAL, ...) cost the robot memory
// that mlockall() pins (371 MB against 99 MB without them), start-up time (13-21 s under
// emulation) and a 110 MiB initramfs, all for a camera backend that only a configuration with
// [camera] backend = "opencv" uses. So the binary never links OpenCV: it loads the module then,
// from ../lib/ringlet/ beside its own folder (/usr/bin/ringlet → /usr/lib/ringlet/; the build tree
// puts the module at the same place relative to firmware/ringlet).
//
// Both sides are built from one tree with one compiler, so the request may hold C++ types; the
// ABI number still refuses a module left over from another build.
#include <string>

#include "ringlet/hal/camera.hpp"
#include "ringlet/hal/clock.hpp"

namespace ringlet::firmware {

inline constexpr int kOpenCvCameraAbi = 1;
/// The module's entry point (extern "C", looked up with dlsym).
inline constexpr const char* kOpenCvCameraEntry = "ringlet_open_opencv_camera";
/// Where the module lies relative to the folder of the binary that loads it.
inline constexpr const char* kOpenCvCameraModule = "../lib/ringlet/ringlet_camera_opencv.so";

struct OpenCvCameraRequest {
  int abi = kOpenCvCameraAbi;
  std::string source;  // camera.source
  int width = 640;
  int height = 480;
  hal::PixelFormat format = hal::PixelFormat::kYuyv;
  const hal::Clock* clock = nullptr;  // stamps the frames
  std::string error;                  // out: why no camera was made
};

/// Makes the camera (the caller owns it: delete through hal::Camera's virtual destructor), or
/// returns null with `error` set. Never throws.
using OpenCvCameraEntry = hal::Camera* (*)(OpenCvCameraRequest& request) noexcept;

}  // namespace ringlet::firmware
