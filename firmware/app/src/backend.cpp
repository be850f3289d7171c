#include "ringlet/firmware/stack.hpp"

#ifdef RINGLET_HAVE_OPENCV_CAMERA
#include "ringlet/hal/opencv_camera.hpp"
#endif

namespace ringlet::firmware {

std::unique_ptr<hal::Robot> make_robot(const FirmwareConfig& config) {
  if (config.backend == "sim") {
    sim::World world = sim::load_world(config.world);
    try {
      return std::make_unique<sim::SimRobot>(std::move(world), config.sim);
    } catch (const std::invalid_argument& e) {
      throw ConfigError(config.source.string() + ": sim: " + e.what());
    }
  }
  throw ConfigError(config.source.string() + ": robot.backend: \"" + config.backend +
                    "\" is not available in this build yet (the SocketCAN backend arrives with the real-board "
                    "work); use \"sim\"");
}

std::unique_ptr<hal::Camera> make_camera(const FirmwareConfig& config, const hal::Clock& clock) {
  if (!config.camera.enabled || config.camera.backend != "opencv") return nullptr;
#ifdef RINGLET_HAVE_OPENCV_CAMERA
  hal::OpenCvCameraConfig c;
  c.source = config.camera.source;
  c.width = config.camera.intrinsics.width;
  c.height = config.camera.intrinsics.height;
  c.format = config.camera.format;
  try {
    return std::make_unique<hal::OpenCvCamera>(c, clock);
  } catch (const hal::CameraError& e) {
    throw ConfigError(config.source.string() + ": camera: " + e.what());
  }
#else
  (void)clock;
  throw ConfigError(config.source.string() + ": camera.backend: this build has no OpenCV camera (OpenCV was not found)");
#endif
}

std::unique_ptr<vision::VisionPipeline> make_vision(const FirmwareConfig& config) {
  vision::ColourTable table = vision::ColourTable::from_thresholds(vision::ColourThresholds{});
  if (!config.vision.lut.empty()) {
    vision::ColourTableLoad loaded = vision::ColourTable::load(config.vision.lut);
    if (!loaded.table) throw ConfigError(config.source.string() + ": vision.lut: " + loaded.error);
    table = std::move(*loaded.table);
  }
  vision::VisionConfig v;
  v.intrinsics = config.camera.intrinsics;
  v.mount = config.camera.mount;
  v.ransac.max_trials = config.vision.max_trials;
  v.ransac.skip = config.vision.skip;
  v.ransac.seed = config.vision.seed;
  return std::make_unique<vision::VisionPipeline>(v, std::move(table));
}

std::vector<behaviour::Waypoint> mission_goals(const hal::Robot& robot) {
  std::vector<behaviour::Waypoint> goals;
  if (const auto* s = dynamic_cast<const sim::SimRobot*>(&robot)) {
    for (const auto& g : s->world().goals) goals.push_back({g.x, g.y});
  }
  return goals;
}

}  // namespace ringlet::firmware
