#pragma once
// The OpenCV camera of [camera] backend = "opencv" (a V4L2 device, a video file or an image
// folder), for FirmwareStack's `opencv_camera` parameter (firmware/camera_opencv/CMakeLists.txt).
#include <memory>

#include "ringlet/firmware/config.hpp"
#include "ringlet/hal/camera.hpp"
#include "ringlet/hal/clock.hpp"

namespace ringlet::firmware {

/// Loads the OpenCV camera module (opencv_camera_plugin.hpp) and opens camera.source with the
/// configured size and format. A module that cannot be loaded is a ConfigError naming
/// camera.backend's file:line:col and the module's path; a source that cannot be opened, one
/// naming camera.source's. `clock` stamps the frames.
[[nodiscard]] std::unique_ptr<hal::Camera> make_opencv_camera(const FirmwareConfig& config, const hal::Clock& clock);

}  // namespace ringlet::firmware
