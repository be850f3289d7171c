// The module ringlet_camera_opencv.so: the one symbol the `ringlet` binary looks up
// (opencv_camera_plugin.hpp), around hal::OpenCvCamera.
#include <exception>

#include "ringlet/firmware/opencv_camera_plugin.hpp"
#include "ringlet/hal/opencv_camera.hpp"

extern "C" [[gnu::visibility("default")]] ringlet::hal::Camera* ringlet_open_opencv_camera(
    ringlet::firmware::OpenCvCameraRequest& request) noexcept {
  if (request.abi != ringlet::firmware::kOpenCvCameraAbi) {
    request.error = "the module was built for another ringlet (plugin ABI " +
                    std::to_string(ringlet::firmware::kOpenCvCameraAbi) + ", the binary asks for " +
                    std::to_string(request.abi) + ")";
    return nullptr;
  }
  ringlet::hal::OpenCvCameraConfig c;
  c.source = request.source;
  c.width = request.width;
  c.height = request.height;
  c.format = request.format;
  try {
    return new ringlet::hal::OpenCvCamera(c, *request.clock);
  } catch (const std::exception& e) {  // CameraError, or OpenCV's own
    request.error = e.what();
    return nullptr;
  }
}
