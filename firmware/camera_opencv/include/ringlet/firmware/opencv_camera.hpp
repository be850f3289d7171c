#pragma once
// The OpenCV camera of [camera] backend = "opencv" (a V4L2 device, a video file or an image
// folder), for FirmwareStack's `opencv_camera` parameter (firmware/camera_opencv/CMakeLists.txt).
#include <memory>

#include "ringlet/firmware/config.hpp"
#include "ringlet/hal/camera.hpp"
#include "ringlet/hal/clock.hpp"

namespace ringlet::firmware {

/// Opens camera.source with the configured size and format; a source that cannot be opened is a
/// ConfigError naming camera.source's file:line:col. `clock` stamps the frames.
[[nodiscard]] std::unique_ptr<hal::Camera> make_opencv_camera(const FirmwareConfig& config, const hal::Clock& clock);

}  // namespace ringlet::firmware
