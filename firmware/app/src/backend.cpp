#include "ringlet/firmware/stack.hpp"

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

std::vector<behaviour::Waypoint> mission_goals(const hal::Robot& robot) {
  std::vector<behaviour::Waypoint> goals;
  if (const auto* s = dynamic_cast<const sim::SimRobot*>(&robot)) {
    for (const auto& g : s->world().goals) goals.push_back({g.x, g.y});
  }
  return goals;
}

}  // namespace ringlet::firmware
