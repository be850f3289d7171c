#include "ringlet/firmware/opencv_camera.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <string>

#include "ringlet/firmware/opencv_camera_plugin.hpp"

namespace ringlet::firmware {
namespace {

/// The module beside this program: kOpenCvCameraModule from the folder /proc/self/exe is in.
std::filesystem::path module_path() {
  std::array<char, 4096> exe{};
  const ssize_t n = ::readlink("/proc/self/exe", exe.data(), exe.size() - 1);
  const std::filesystem::path dir =
      n > 0 ? std::filesystem::path(std::string(exe.data(), static_cast<std::size_t>(n))).parent_path()
            : std::filesystem::current_path();
  return (dir / kOpenCvCameraModule).lexically_normal();
}

/// The entry point, from the module loaded once for the program's life (OpenCV's threads and
/// statics must not be unloaded under a running camera); why not in `error`.
OpenCvCameraEntry entry(std::string& error) {
  static OpenCvCameraEntry loaded = nullptr;
  if (loaded != nullptr) return loaded;
  const std::string path = module_path().string();
  void* module = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (module == nullptr) {
    const char* why = ::dlerror();
    error = "cannot load the OpenCV camera module " + path + ": " + (why != nullptr ? why : "unknown error");
    return nullptr;
  }
  void* symbol = ::dlsym(module, kOpenCvCameraEntry);
  if (symbol == nullptr) {
    error = path + " is not the OpenCV camera module (no " + kOpenCvCameraEntry + ")";
    return nullptr;
  }
  loaded = reinterpret_cast<OpenCvCameraEntry>(symbol);
  return loaded;
}

}  // namespace

std::unique_ptr<hal::Camera> make_opencv_camera(const FirmwareConfig& config, const hal::Clock& clock) {
  std::string error;
  const OpenCvCameraEntry open = entry(error);
  if (open == nullptr) throw ConfigError(config.positions.at("camera.backend") + ": camera.backend: " + error);
  OpenCvCameraRequest request;
  request.source = config.camera.source;
  request.width = config.camera.intrinsics.width;
  request.height = config.camera.intrinsics.height;
  request.format = config.camera.format;
  request.clock = &clock;
  std::unique_ptr<hal::Camera> camera(open(request));
  if (!camera) throw ConfigError(config.positions.at("camera.source") + ": camera.source: " + request.error);
  return camera;
}

}  // namespace ringlet::firmware
