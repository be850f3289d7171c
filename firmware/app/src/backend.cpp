#include "ringlet/firmware/stack.hpp"

#include <sstream>

#include "ringlet/sim_hal/collision.hpp"

#ifdef RINGLET_HAVE_OPENCV_CAMERA
#include "ringlet/hal/opencv_camera.hpp"
#endif

namespace ringlet::firmware {

namespace {

// The world named by sim.world; a file that cannot be read is named with the key that named it.
sim_hal::World load_world_of(const FirmwareConfig& config) {
  try {
    return sim_hal::load_world(config.world);
  } catch (const sim_hal::WorldError& e) {
    const std::string message = e.what();
    // Errors inside the world file already say "<world>:<line>:"; only add where the key is.
    if (message.rfind(config.world.string() + ": cannot read", 0) != 0) throw;
    throw sim_hal::WorldError(config.positions.at("sim.world") + ": sim.world: " + message);
  }
}

}  // namespace

std::unique_ptr<hal::Robot> make_robot(const FirmwareConfig& config) {
  if (config.backend == "sim") {
    sim_hal::World world = load_world_of(config);
    // Checked here, not only in SimRobot, so that the message names both places: the world's
    // start line and the configuration's robot radius.
    if (sim_hal::disc_collides(world, sim_hal::Vec2{world.start.x, world.start.y}, config.sim.robot_radius)) {
      std::ostringstream s;
      s << config.world.string() << ':' << world.start_line << ": start pose (" << world.start.x << ", "
        << world.start.y << ") collides with an obstacle or the bounds for a robot of radius "
        << config.sim.robot_radius << " m (sim.robot_radius, " << config.positions.at("sim.robot_radius") << ")";
      throw sim_hal::WorldError(s.str());
    }
    try {
      return std::make_unique<sim_hal::SimRobot>(std::move(world), config.sim);
    } catch (const std::invalid_argument& e) {
      throw ConfigError(config.positions.at("sim") + ": sim: " + e.what());
    }
  }
  throw ConfigError(config.positions.at("robot.backend") + ": robot.backend: \"" + config.backend +
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
    throw ConfigError(config.positions.at("camera.source") + ": camera.source: " + e.what());
  }
#else
  (void)clock;
  throw ConfigError(config.positions.at("camera.backend") +
                    ": camera.backend: this build has no OpenCV camera (OpenCV was not found)");
#endif
}

std::unique_ptr<vision::VisionPipeline> make_vision(const FirmwareConfig& config) {
  vision::ColourTable table = vision::ColourTable::from_thresholds(vision::ColourThresholds{});
  if (!config.vision.lut.empty()) {
    vision::ColourTableLoad loaded = vision::ColourTable::load(config.vision.lut);
    if (!loaded.table) throw ConfigError(config.positions.at("vision.lut") + ": vision.lut: " + loaded.error);
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
  if (const auto* s = dynamic_cast<const sim_hal::SimRobot*>(&robot)) {
    for (const auto& g : s->world().goals) goals.push_back({g.x, g.y});
  }
  return goals;
}

}  // namespace ringlet::firmware
