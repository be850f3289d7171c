#include "ringlet/firmware/opencv_camera.hpp"

#include "ringlet/hal/opencv_camera.hpp"

namespace ringlet::firmware {

std::unique_ptr<hal::Camera> make_opencv_camera(const FirmwareConfig& config, const hal::Clock& clock) {
  hal::OpenCvCameraConfig c;
  c.source = config.camera.source;
  c.width = config.camera.intrinsics.width;
  c.height = config.camera.intrinsics.height;
  c.format = config.camera.format;
  try {
    return std::make_unique<hal::OpenCvCamera>(c, clock);
  } catch (const hal::CameraError& e) {
    throw ConfigError(config.positions.at("camera.source") + ": camera.source: " + e.what());
  }
}

}  // namespace ringlet::firmware
