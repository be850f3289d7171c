#include "ringlet/firmware/backend_factory.hpp"

#include <sstream>

#include "config_section.hpp"
#include "ringlet/hal/can/can_robot.hpp"
#include "ringlet/hal/monotonic_clock.hpp"
#include "ringlet/hal/replay_robot.hpp"
#include "ringlet/sim_hal/collision.hpp"
#include "ringlet/sim_hal/world_raster.hpp"
#include "ringlet/sim_hal/sim_robot.hpp"
#include "ringlet/sim_hal/world.hpp"
#include "ringlet/sim_hal/world_svg.hpp"

namespace ringlet::firmware {
namespace {

// ---- sim: the simulated robot in a world file --------------------------------------------------

struct SimSettings final : BackendSettings {
  std::filesystem::path world;  // sim.world, resolved relative to the configuration file
  sim_hal::SimConfig sim{};     // its period, seed override and camera come from the rest at make_robot

  [[nodiscard]] std::string source_name() const override { return world.filename().string(); }
  [[nodiscard]] std::optional<std::uint64_t> seed() const override { return sim.seed; }
};

std::shared_ptr<const BackendSettings> read_sim(Section& section, const std::filesystem::path& base_dir,
                                                const FirmwareConfig& so_far) {
  auto out = std::make_shared<SimSettings>();
  out->world = section.path("world", base_dir);
  if (out->world.empty() && so_far.backend == "sim") {
    section.fail_missing("world", "the simulated robot needs a world file (sim.world = \"...\")");
  }
  auto& s = out->sim;
  s.seed = section.unsigned_integer("seed", s.seed);
  s.limits.max_speed = section.number("max_speed", s.limits.max_speed, 0.01, 20.0);
  s.limits.max_curvature = section.number("max_curvature", s.limits.max_curvature, 0.01, 100.0);
  s.limits.max_acceleration = section.number("max_acceleration", s.limits.max_acceleration, 0.01, 100.0);
  s.limits.max_curvature_rate = section.number("max_curvature_rate", s.limits.max_curvature_rate, 0.01, 1000.0);
  s.robot_radius = section.number("robot_radius", s.robot_radius, 0.01, 5.0);
  s.gps_sigma_xy = section.number("gps_sigma_xy", s.gps_sigma_xy, 0.0, 10.0);
  s.gps_sigma_theta = hal::deg_to_rad(section.number("gps_sigma_theta_deg", hal::rad_to_deg(s.gps_sigma_theta), 0.0, 90.0));
  // Wheel odometry's errors (SimOdometryError): exact unless configured.
  s.odometry.scale = section.number("odometry_scale", s.odometry.scale, 0.5, 1.5);
  s.odometry.curvature_bias = section.number("odometry_curvature_bias", s.odometry.curvature_bias, -1.0, 1.0);
  s.odometry.slip_sigma = section.number("odometry_slip_sigma", s.odometry.slip_sigma, 0.0, 1.0);
  s.odometry.curvature_sigma = section.number("odometry_curvature_sigma", s.odometry.curvature_sigma, 0.0, 1.0);
  s.laser_beams = section.integer("laser_beams", s.laser_beams, 1, static_cast<int>(hal::LaserScan::kMaxBeams));
  s.laser_fov = hal::deg_to_rad(section.number("laser_fov_deg", hal::rad_to_deg(s.laser_fov), 0.1, 360.0));
  s.laser_range = section.number("laser_range", s.laser_range, 0.1, 100.0);
  s.laser_sigma = section.number("laser_sigma", s.laser_sigma, 0.0, 10.0);
  s.head_max_rate = section.number("head_max_rate", s.head_max_rate, 0.01, 100.0);
  // The torso's tilt (degrees here, radians in SimBodyTilt); SimRobot checks lean + sway together.
  using Tilt = hal::BodyTiltRange;
  const auto degrees = [&](const char* key, double rad, double max_deg) {
    return hal::deg_to_rad(section.number(key, hal::rad_to_deg(rad), -max_deg, max_deg));
  };
  s.body.pitch = degrees("body_pitch_deg", s.body.pitch, Tilt::kMaxPitchDeg);
  s.body.roll = degrees("body_roll_deg", s.body.roll, Tilt::kMaxRollDeg);
  s.body.sway_pitch = hal::deg_to_rad(section.number("body_sway_pitch_deg", hal::rad_to_deg(s.body.sway_pitch), 0.0, 10.0));
  s.body.sway_roll = hal::deg_to_rad(section.number("body_sway_roll_deg", hal::rad_to_deg(s.body.sway_roll), 0.0, 10.0));
  s.body.sway_period = section.number("body_sway_period", s.body.sway_period, 0.05, 60.0);
  // A referee's pick-up: sim.kidnap = { at_s = 10.0, x = 1.0, y = -2.0, theta_deg = 90 }.
  Section kidnap = section.sub("kidnap", "{ at_s = 10.0, x = 1.0, y = -2.0, theta_deg = 90 }");
  if (kidnap.present()) {
    for (const char* key : {"at_s", "x", "y"}) {
      if (kidnap.find(key) == nullptr) kidnap.fail_missing(key, "required in sim.kidnap");
    }
    s.kidnap.enabled = true;
    s.kidnap.at_s = kidnap.number("at_s", 0.0, 0.0, 1e6);
    s.kidnap.to.x = kidnap.number("x", 0.0, -1e3, 1e3);
    s.kidnap.to.y = kidnap.number("y", 0.0, -1e3, 1e3);
    s.kidnap.to.theta = hal::wrap_angle(hal::deg_to_rad(kidnap.number("theta_deg", 0.0, -360.0, 360.0)));
    kidnap.reject_unknown();
  }
  return out;
}

// The world named by sim.world; a file that cannot be read is named with the key that named it.
sim_hal::World load_world_of(const FirmwareConfig& config, const SimSettings& settings) {
  try {
    return sim_hal::load_world(settings.world);
  } catch (const sim_hal::WorldError& e) {
    const std::string message = e.what();
    // Errors inside the world file already say "<world>:<line>:"; only add where the key is.
    if (message.rfind(settings.world.string() + ": cannot read", 0) != 0) throw ConfigError(message);
    throw ConfigError(config.positions.at("sim.world") + ": sim.world: " + message);
  }
}

// The simulated robot is its own ground truth; the picture is its world with the run drawn on.
class SimBackend final : public sim_hal::SimRobot, private hal::GroundTruth {
 public:
  using sim_hal::SimRobot::SimRobot;
  [[nodiscard]] const hal::GroundTruth* ground_truth() const noexcept override { return this; }

 private:
  [[nodiscard]] std::optional<hal::RobotPoint> ball_in_robot_frame() const noexcept override {
    return true_ball_in_robot_frame();
  }
  [[nodiscard]] std::uint64_t collisions() const noexcept override { return SimRobot::collisions(); }
  [[nodiscard]] double distance_travelled() const noexcept override { return SimRobot::distance_travelled(); }
  [[nodiscard]] std::optional<hal::Pose2> robot_pose() const noexcept override { return true_state().pose; }
  void write_picture(std::ostream& out, const hal::RunPicture& run) const override {
    sim_hal::write_world_svg(out, world(), run);
  }
};

std::unique_ptr<hal::Robot> make_sim(const FirmwareConfig& config, const SimSettings& settings) {
  sim_hal::World world = load_world_of(config, settings);
  sim_hal::SimConfig sim = settings.sim;
  sim.period = config.executive.period;
  sim.seed = config.seed();
  if (const executive::TaskSpec* vision = config.task("vision"); vision != nullptr && config.camera.backend == "robot") {
    // The rendered camera delivers a frame whenever vision runs: one setting, the vision row's.
    sim.camera = {true, config.camera.intrinsics, config.camera.mount, config.camera.format, vision->every};
  }
  // A goal outside the world can never be reached: refused before the run, naming both places.
  for (std::size_t i = 0; i < config.mission.goals.size(); ++i) {
    const auto& g = config.mission.goals[i];
    if (g.x < world.min.x || g.x > world.max.x || g.y < world.min.y || g.y > world.max.y) {
      const std::string key = "mission.goals[" + std::to_string(i) + "]";
      std::ostringstream s;
      s << config.positions.at(key) << ": " << key << ": (" << g.x << ", " << g.y << ") lies outside the world "
        << settings.world.string() << " (bounds " << world.min.x << ' ' << world.min.y << ' ' << world.max.x << ' '
        << world.max.y << ')';
      throw ConfigError(s.str());
    }
  }
  // Checked here, not only in SimRobot, so that the message names both places: the world's
  // start line and the configuration's robot radius.
  if (sim_hal::disc_collides(world, sim_hal::Vec2{world.start.x, world.start.y}, sim.robot_radius)) {
    std::ostringstream s;
    s << settings.world.string() << ':' << world.start_line << ": start pose (" << world.start.x << ", "
      << world.start.y << ") collides with an obstacle or the bounds for a robot of radius " << sim.robot_radius
      << " m (sim.robot_radius, " << config.positions.at("sim.robot_radius") << ")";
    throw ConfigError(s.str());
  }
  try {
    return std::make_unique<SimBackend>(std::move(world), sim);
  } catch (const std::invalid_argument& e) {
    throw ConfigError(config.positions.at("sim") + ": sim: " + e.what());
  }
}

// ---- replay: a recorded run's HAL inputs, fed back through the same firmware -------------------

struct ReplaySettings final : BackendSettings {
  std::filesystem::path log;  // replay.log, resolved relative to the configuration file

  [[nodiscard]] std::string source_name() const override { return log.filename().string(); }
  [[nodiscard]] std::optional<std::uint64_t> seed() const override { return std::nullopt; }
};

std::shared_ptr<const BackendSettings> read_replay(Section& section, const std::filesystem::path& base_dir,
                                                   const FirmwareConfig& so_far) {
  auto out = std::make_shared<ReplaySettings>();
  out->log = section.path("log", base_dir);
  if (out->log.empty() && so_far.backend == "replay") {
    section.fail_missing("log", "the replay backend needs a log recorded with ringlet --record (replay.log = \"...\")");
  }
  return out;
}

std::unique_ptr<hal::Robot> make_replay(const FirmwareConfig& config, const ReplaySettings& settings) {
  if (config.clock != ClockMode::kLockstep) {
    // The replay reads its log on the cycle's thread: only virtual time makes that harmless.
    throw ConfigError(config.positions.at("executive.clock") +
                      ": executive.clock: a replay runs in lockstep (it reads the log on the cycle's thread)");
  }
  std::unique_ptr<hal::ReplayRobot> robot;
  try {
    robot = std::make_unique<hal::ReplayRobot>(settings.log);
  } catch (const hal::LogError& e) {
    throw ConfigError(config.positions.at("replay.log") + ": replay.log: " + e.what());
  }
  if (robot->period() != config.executive.period) {
    throw ConfigError(config.positions.at("executive.period_us") + ": executive.period_us: the log " +
                      settings.log.string() + " was recorded with a period of " +
                      std::to_string(robot->period().count() / 1000) + " us, the configuration has " +
                      std::to_string(config.executive.period.count() / 1000) + " us");
  }
  return robot;
}

// ---- can: the real board over SocketCAN (hal/can/README.md) -------------------------------------

struct CanBackendSettings final : BackendSettings {
  hal::can::CanSettings can{};

  [[nodiscard]] std::string source_name() const override { return "CAN " + can.interface; }
  [[nodiscard]] std::optional<std::uint64_t> seed() const override { return std::nullopt; }
};

std::shared_ptr<const BackendSettings> read_can(Section& section, const FirmwareConfig& /*so_far*/) {
  auto out = std::make_shared<CanBackendSettings>();
  auto& c = out->can;
  c.interface = section.text("interface", c.interface);
  if (c.interface.empty() || c.interface.size() > 15) {
    section.fail(*section.find("interface"), "interface", "must be a network interface name of 1 to 15 characters, e.g. \"can0\" or \"vcan0\"");
  }
  const auto ms = [&](const char* key, std::chrono::milliseconds def, int lo, int hi) {
    return std::chrono::milliseconds{section.integer(key, static_cast<int>(def.count()), lo, hi)};
  };
  c.heartbeat_timeout = ms("heartbeat_timeout_ms", c.heartbeat_timeout, 20, 10000);
  c.sensor_timeout = ms("sensor_timeout_ms", c.sensor_timeout, 5, 10000);
  c.laser_timeout = ms("laser_timeout_ms", c.laser_timeout, 20, 10000);
  c.reconnect_period = ms("reconnect_ms", c.reconnect_period, 10, 60000);
  c.max_frames_per_read = section.integer("max_frames_per_read", c.max_frames_per_read, 1, 100000);
  return out;
}

// The board on the real clock: CanRobot ages its sensors on CLOCK_MONOTONIC, the clock the
// executive's real-time mode runs on.
class CanBackend final : public hal::Robot {
 public:
  explicit CanBackend(const hal::can::CanSettings& s, std::string& error) : robot_(hal::can::CanRobot::open(s, clock_, error)) {}
  [[nodiscard]] bool ok() const noexcept { return robot_ != nullptr; }
  [[nodiscard]] std::string_view backend_name() const noexcept override { return "can"; }
  hal::Sensors& sensors() noexcept override { return robot_->sensors(); }
  hal::Actuators& actuators() noexcept override { return robot_->actuators(); }
  hal::Camera* camera() noexcept override { return nullptr; }
  [[nodiscard]] const hal::BoardHealth* board_health() const noexcept override { return robot_->board_health(); }

 private:
  hal::MonotonicClock clock_;
  std::unique_ptr<hal::can::CanRobot> robot_;
};

std::unique_ptr<hal::Robot> make_can(const FirmwareConfig& config, const CanBackendSettings& settings) {
  if (config.clock != ClockMode::kRealtime) {
    throw ConfigError(config.positions.at("executive.clock") +
                      ": executive.clock: the CAN board runs on the real clock (executive.clock = \"realtime\" or --realtime)");
  }
  std::string error;
  auto robot = std::make_unique<CanBackend>(settings.can, error);
  if (!robot->ok()) throw ConfigError(config.positions.at("can.interface") + ": can.interface: " + error);
  return robot;
}

}  // namespace

const std::vector<std::string>& backend_names() {
  static const std::vector<std::string> names{"sim", "replay", "can"};
  return names;
}

std::shared_ptr<const BackendSettings> read_backend_settings(const std::string& name, Section& section,
                                                             const std::filesystem::path& base_dir,
                                                             const FirmwareConfig& so_far) {
  if (name == "sim") return read_sim(section, base_dir, so_far);
  if (name == "replay") return read_replay(section, base_dir, so_far);
  if (name == "can") return read_can(section, so_far);
  throw ConfigError("robot.backend: no reader for backend \"" + name + "\"");
}

planning::MovingAiMap sim_world_map(const FirmwareConfig& config) {
  if (config.backend != "sim" || !config.backend_settings) {
    throw ConfigError(config.positions.at("robot.backend") + ": robot.backend: \"" + config.backend +
                      "\", not \"sim\": there is no world to map");
  }
  const auto& settings = static_cast<const SimSettings&>(*config.backend_settings);
  const planning::MapConfig& map = config.planner.map;
  const std::vector<std::uint8_t> blocked = sim_hal::blocked_cells(
      load_world_of(config, settings), {map.origin_x, map.origin_y, map.resolution, map.width_cells, map.height_cells});
  planning::MovingAiMap m;
  m.width = map.width_cells;
  m.height = map.height_cells;
  m.terrain.reserve(blocked.size());
  for (int row = 0; row < m.height; ++row) {
    const std::size_t south_row = static_cast<std::size_t>(m.height - 1 - row) * static_cast<std::size_t>(m.width);
    for (int x = 0; x < m.width; ++x) m.terrain.push_back(blocked[south_row + static_cast<std::size_t>(x)] != 0 ? '@' : '.');
  }
  return m;
}

const hal::can::CanSettings* can_settings(const FirmwareConfig& config) noexcept {
  if (config.backend != "can" || !config.backend_settings) return nullptr;
  return &static_cast<const CanBackendSettings&>(*config.backend_settings).can;
}

std::unique_ptr<hal::Robot> make_robot(const FirmwareConfig& config) {
  if (config.backend == "sim") return make_sim(config, static_cast<const SimSettings&>(*config.backend_settings));
  if (config.backend == "replay") {
    return make_replay(config, static_cast<const ReplaySettings&>(*config.backend_settings));
  }
  if (config.backend == "can") return make_can(config, static_cast<const CanBackendSettings&>(*config.backend_settings));
  throw ConfigError(config.positions.at("robot.backend") + ": robot.backend: \"" + config.backend +
                    "\" is not a backend of this build");
}

std::unique_ptr<hal::Camera> make_camera(const FirmwareConfig& config, const hal::Clock& clock,
                                         OpenCvCameraMaker opencv_camera) {
  if (config.task("vision") == nullptr || config.camera.backend != "opencv") return nullptr;
  if (opencv_camera == nullptr) {
    throw ConfigError(config.positions.at("camera.backend") +
                      ": camera.backend: this program was built without the OpenCV camera");
  }
  return opencv_camera(config, clock);
}

}  // namespace ringlet::firmware
