#include "ringlet/firmware/config.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include <toml++/toml.h>

#include "ringlet/hal/geometry.hpp"
#include "ringlet/hal/read_file.hpp"

namespace ringlet::firmware {
namespace {

std::string where(const std::string& file, const toml::source_region& r) {
  std::ostringstream s;
  s << file << ':' << r.begin.line << ':' << r.begin.column;
  return s.str();
}

// One TOML table with the keys this firmware knows. Every read checks type and range; unknown
// keys are refused at the end so that typos surface.
class Section {
 public:
  Section(const toml::table* table, std::string name, const std::string& file, const toml::source_region& fallback)
      : table_(table), name_(std::move(name)), file_(file), fallback_(fallback) {}

  [[nodiscard]] bool present() const { return table_ != nullptr; }

  double number(const std::string& key, double fallback, double lo, double hi) {
    const toml::node* n = find(key);
    if (n == nullptr) return fallback;
    double v = 0.0;
    if (const auto* i = n->as_integer()) {
      v = static_cast<double>(i->get());
    } else if (const auto* f = n->as_floating_point()) {
      v = f->get();
    } else {
      fail(*n, key, "must be a number");
    }
    if (!std::isfinite(v) || v < lo || v > hi) {
      std::ostringstream s;
      s << "must be between " << lo << " and " << hi << ", got " << v;
      fail(*n, key, s.str());
    }
    return v;
  }

  int integer(const std::string& key, int fallback, int lo, int hi) {
    const toml::node* n = find(key);
    if (n == nullptr) return fallback;
    const auto* i = n->as_integer();
    if (i == nullptr) fail(*n, key, "must be an integer");
    if (i->get() < lo || i->get() > hi) {
      fail(*n, key, "must be between " + std::to_string(lo) + " and " + std::to_string(hi) + ", got " +
                        std::to_string(i->get()));
    }
    return static_cast<int>(i->get());
  }

  std::uint64_t unsigned_integer(const std::string& key, std::uint64_t fallback) {
    const toml::node* n = find(key);
    if (n == nullptr) return fallback;
    const auto* i = n->as_integer();
    if (i == nullptr || i->get() < 0) fail(*n, key, "must be a non-negative integer");
    return static_cast<std::uint64_t>(i->get());
  }

  bool boolean(const std::string& key, bool fallback) {
    const toml::node* n = find(key);
    if (n == nullptr) return fallback;
    const auto* b = n->as_boolean();
    if (b == nullptr) fail(*n, key, "must be true or false");
    return b->get();
  }

  std::string text(const std::string& key, const std::string& fallback, const std::vector<std::string>& allowed = {}) {
    const toml::node* n = find(key);
    if (n == nullptr) return fallback;
    const auto* s = n->as_string();
    if (s == nullptr) fail(*n, key, "must be a string");
    if (!allowed.empty()) {
      bool ok = false;
      std::string list;
      for (const auto& a : allowed) {
        ok = ok || a == s->get();
        list += (list.empty() ? "\"" : ", \"") + a + "\"";
      }
      if (!ok) fail(*n, key, "must be one of " + list + ", got \"" + s->get() + "\"");
    }
    return s->get();
  }

  const toml::node* find(const std::string& key) {
    used_.insert(key);
    return table_ == nullptr ? nullptr : table_->get(key);
  }

  [[noreturn]] void fail(const toml::node& n, const std::string& key, const std::string& message) const {
    throw ConfigError(where(file_, n.source()) + ": " + qualified(key) + ": " + message);
  }
  [[noreturn]] void fail_missing(const std::string& key, const std::string& message) const {
    const auto& region = table_ != nullptr ? table_->source() : fallback_;
    throw ConfigError(where(file_, region) + ": " + qualified(key) + ": " + message);
  }

  void reject_unknown() const {
    if (table_ == nullptr) return;
    for (auto&& [k, v] : *table_) {
      if (!used_.contains(std::string(k.str()))) {
        throw ConfigError(where(file_, v.source()) + ": " + qualified(std::string(k.str())) + ": unknown key" +
                          (name_.empty() ? "" : " in [" + name_ + "]"));
      }
    }
  }

 private:
  [[nodiscard]] std::string qualified(const std::string& key) const { return name_.empty() ? key : name_ + "." + key; }

  const toml::table* table_;
  std::string name_;
  const std::string& file_;
  const toml::source_region& fallback_;
  std::set<std::string> used_;
};

Section section(const toml::table& root, Section& top, const std::string& name, const std::string& file) {
  const toml::node* n = top.find(name);
  if (n != nullptr && n->as_table() == nullptr) top.fail(*n, name, "must be a table, e.g. [" + name + "]");
  return Section(n != nullptr ? n->as_table() : nullptr, name, file, root.source());
}

void read_tasks(Section& exec, FirmwareConfig& cfg, const std::string& file, const toml::source_region& fallback) {
  const toml::node* n = exec.find("tasks");
  if (n == nullptr) exec.fail_missing("tasks", "the task table is missing (an array of { name, every, phase, budget_us, policy })");
  const auto* rows = n->as_array();
  if (rows == nullptr) exec.fail(*n, "tasks", "must be an array of tables");
  if (rows->size() > executive::kMaxTasks) {
    exec.fail(*n, "tasks", "has " + std::to_string(rows->size()) + " rows; at most " +
                               std::to_string(executive::kMaxTasks) + " are allowed");
  }
  const double base_hz = 1e9 / static_cast<double>(cfg.executive.period.count());
  for (std::size_t i = 0; i < rows->size(); ++i) {
    const toml::node& row_node = *rows->get(i);
    const auto* row = row_node.as_table();
    if (row == nullptr) exec.fail(row_node, "tasks[" + std::to_string(i) + "]", "must be a table { name = ..., ... }");
    Section r(row, "executive.tasks[" + std::to_string(i) + "]", file, fallback);
    executive::TaskSpec t;
    t.name = r.text("name", "");
    if (t.name.empty()) r.fail_missing("name", "every task needs a name");
    const toml::node* every = r.find("every");
    const toml::node* rate = r.find("rate_hz");
    if (every != nullptr && rate != nullptr) r.fail(*rate, "rate_hz", "give either every or rate_hz, not both");
    if (rate != nullptr) {
      const double hz = r.number("rate_hz", base_hz, 1e-3, base_hz);
      const double divisor = base_hz / hz;
      if (std::abs(divisor - std::round(divisor)) > 1e-6) {
        std::ostringstream s;
        s << "rate " << hz << " Hz does not divide the base rate " << base_hz << " Hz (rates available: " << base_hz
          << ", " << base_hz / 2 << ", " << base_hz / 3 << ", " << base_hz / 4 << ", " << base_hz / 5 << ", ...)";
        r.fail(*rate, "rate_hz", s.str());
      }
      t.every = static_cast<int>(std::lround(divisor));
    } else {
      t.every = r.integer("every", 1, 1, 100000);
    }
    t.phase = r.integer("phase", 0, 0, t.every - 1);
    // Whole microseconds: a fraction would be cut off silently by the conversion, and no budget
    // needs sub-microsecond precision.
    const toml::node* budget = r.find("budget_us");
    if (budget == nullptr) r.fail_missing("budget_us", "every task needs a budget in microseconds");
    const double budget_us = r.number("budget_us", 0.0, 1.0, 1e7);
    if (budget_us != std::floor(budget_us)) {
      std::ostringstream s;
      s << "must be a whole number of microseconds, got " << budget_us;
      r.fail(*budget, "budget_us", s.str());
    }
    t.budget = hal::from_micros(static_cast<std::int64_t>(budget_us));
    const std::string policy = r.text("policy", "warn", {"warn", "skip", "degrade", "failsafe"});
    (void)executive::parse_policy(policy, t.policy);
    r.reject_unknown();
    cfg.tasks.push_back(std::move(t));
  }
  if (auto problems = executive::validate(cfg.executive, cfg.tasks); !problems.empty()) {
    std::string text = where(file, n->source()) + ": executive.tasks: invalid task table:";
    for (const auto& p : problems) text += "\n  - " + p;
    throw ConfigError(text);
  }
}

// Every key's "file:line:col", for errors found after parsing. Called once the file has been
// accepted, so the tree holds only known keys and at most kMaxTasks task rows.
void record(const toml::node& node, const std::string& key, const std::string& file, ConfigPositions& out) {
  if (!key.empty()) out.keys.emplace(key, where(file, node.source()));
  if (const auto* table = node.as_table()) {
    for (auto&& [k, v] : *table) record(v, key.empty() ? std::string(k.str()) : key + "." + std::string(k.str()), file, out);
  } else if (const auto* array = node.as_array()) {
    for (std::size_t i = 0; i < array->size(); ++i) record(*array->get(i), key + "[" + std::to_string(i) + "]", file, out);
  }
}

ConfigPositions record_positions(const toml::table& root, const std::string& file) {
  ConfigPositions positions;
  positions.file = file;
  record(root, "", file, positions);
  return positions;
}

}  // namespace

FirmwareConfig parse_config(std::string_view text, const std::string& source, const std::filesystem::path& base_dir) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw ConfigError(where(source, e.source()) + ": " + std::string(e.description()));
  }
  FirmwareConfig cfg;
  cfg.source = source;
  Section top(&root, "", source, root.source());

  Section robot = section(root, top, "robot", source);
  cfg.backend = robot.text("backend", "sim", {"sim", "can"});
  robot.reject_unknown();

  Section exec = section(root, top, "executive", source);
  cfg.executive.period = hal::from_micros(exec.integer("period_us", 10000, 1000, 1000000));
  cfg.clock = exec.text("clock", "lockstep", {"lockstep", "realtime"}) == "realtime" ? ClockMode::kRealtime
                                                                                      : ClockMode::kLockstep;
  cfg.executive.watchdog_periods = exec.integer("watchdog_periods", 5, 0, 1000);
  cfg.executive.warn_every_frames = exec.integer("warn_every_frames", 100, 1, 1000000);
  cfg.executive.degrade_max_level = exec.integer("degrade_max_level", 3, 1, 100);
  cfg.executive.degrade_recover_after = exec.integer("degrade_recover_after", 20, 1, 1000000);
  cfg.executive.overrun_on_cpu_time = exec.text("budgets_judged_on", "wall", {"wall", "cpu"}) == "cpu";
  cfg.realtime.fifo_priority = exec.integer("fifo_priority", 0, 0, 99);
  cfg.realtime.lock_memory = exec.boolean("lock_memory", false);
  cfg.realtime.cpu = exec.integer("cpu", -1, -1, 1023);
  read_tasks(exec, cfg, source, root.source());
  exec.reject_unknown();

  Section sim = section(root, top, "sim", source);
  if (cfg.backend == "sim") {
    const std::string world = sim.text("world", "");
    if (world.empty()) sim.fail_missing("world", "the simulated robot needs a world file (sim.world = \"...\")");
    cfg.world = std::filesystem::path(world).is_absolute() ? std::filesystem::path(world) : base_dir / world;
  } else {
    (void)sim.find("world");
  }
  auto& s = cfg.sim;
  s.period = cfg.executive.period;
  s.seed = sim.unsigned_integer("seed", 1);
  s.limits.max_speed = sim.number("max_speed", 1.0, 0.01, 20.0);
  s.limits.max_curvature = sim.number("max_curvature", 2.0, 0.01, 100.0);
  s.limits.max_acceleration = sim.number("max_acceleration", 1.0, 0.01, 100.0);
  s.limits.max_curvature_rate = sim.number("max_curvature_rate", 4.0, 0.01, 1000.0);
  s.robot_radius = sim.number("robot_radius", 0.25, 0.01, 5.0);
  s.gps_sigma_xy = sim.number("gps_sigma_xy", 0.02, 0.0, 10.0);
  s.gps_sigma_theta = hal::deg_to_rad(sim.number("gps_sigma_theta_deg", 0.5, 0.0, 90.0));
  s.laser_beams = sim.integer("laser_beams", 181, 1, static_cast<int>(hal::LaserScan::kMaxBeams));
  s.laser_fov = hal::deg_to_rad(sim.number("laser_fov_deg", 180.0, 0.1, 360.0));
  s.laser_range = sim.number("laser_range", 8.0, 0.1, 100.0);
  s.laser_sigma = sim.number("laser_sigma", 0.01, 0.0, 10.0);
  s.head_max_rate = sim.number("head_max_rate", 4.0, 0.01, 100.0);
  sim.reject_unknown();

  Section mission = section(root, top, "mission", source);
  cfg.goal_tolerance = mission.number("goal_tolerance_m", 0.3, 0.01, 10.0);
  cfg.timeout_s = mission.number("timeout_s", 300.0, 0.01, kMaxRunSeconds);
  mission.reject_unknown();

  Section follower = section(root, top, "follower", source);
  auto& f = cfg.follower;
  f.gain = follower.number("gain", 2.0, 0.0, 100.0);
  f.max_curvature = follower.number("max_curvature", s.limits.max_curvature, 0.01, 100.0);
  f.max_speed = follower.number("max_speed", s.limits.max_speed, 0.01, 20.0);
  f.min_speed = follower.number("min_speed", 0.2, 0.0, 20.0);
  f.full_turn_error = hal::deg_to_rad(follower.number("full_turn_error_deg", 70.0, 1.0, 180.0));
  f.approach_radius = follower.number("approach_radius_m", 0.0, 0.0, 100.0);
  if (f.min_speed > f.max_speed) {
    if (const toml::node* n = follower.find("min_speed")) follower.fail(*n, "min_speed", "must not exceed max_speed");
    follower.fail_missing("min_speed", "the default 0.2 m/s exceeds max_speed; set min_speed");
  }
  follower.reject_unknown();

  Section safety = section(root, top, "safety", source);
  cfg.safety.stop_range = safety.number("stop_range_m", 0.9, 0.05, 50.0);
  cfg.safety.release_range = safety.number("release_range_m", 1.2, 0.05, 50.0);
  cfg.safety.hold_ms = safety.integer("release_after_ms", 300, 0, 600000);
  if (cfg.safety.release_range <= cfg.safety.stop_range) {
    if (const toml::node* n = safety.find("release_range_m")) {
      safety.fail(*n, "release_range_m", "must be larger than stop_range_m (hysteresis)");
    }
    safety.fail_missing("release_range_m", "must be larger than stop_range_m (hysteresis)");
  }
  safety.reject_unknown();

  Section camera = section(root, top, "camera", source);
  auto& c = cfg.camera;
  c.enabled = camera.boolean("enabled", false);
  c.backend = camera.text("backend", "sim", {"sim", "opencv"});
  c.source = camera.text("source", "");
  const int width = camera.integer("width", 640, 16, 4096);
  const int height = camera.integer("height", 480, 16, 4096);
  if (width % 2 != 0) camera.fail(*camera.find("width"), "width", "must be even (YUYV packs pixel pairs)");
  c.intrinsics = hal::CameraIntrinsics::from_fov(width, height, camera.number("hfov_deg", 57.0, 1.0, 179.0),
                                                 camera.number("vfov_deg", 44.0, 1.0, 179.0));
  c.format = camera.text("format", "yuyv", {"yuyv", "bgr"}) == "bgr" ? hal::PixelFormat::kBgr8 : hal::PixelFormat::kYuyv;
  c.mount.pivot_height = camera.number("pivot_height_m", 0.45, 0.01, 10.0);
  c.mount.forward = camera.number("forward_m", 0.05, -1.0, 1.0);
  c.mount.up = camera.number("up_m", 0.06, -1.0, 1.0);
  c.every_frames = camera.integer("every_frames", 3, 1, 1000);
  if (c.enabled && c.backend == "sim" && cfg.backend != "sim") {
    camera.fail_missing("backend", "the \"sim\" camera needs robot.backend = \"sim\"");
  }
  if (c.enabled && c.backend == "opencv" && c.source.empty()) {
    camera.fail_missing("source", "the \"opencv\" camera needs a source (a device, a video file or an image folder)");
  }
  camera.reject_unknown();
  if (c.enabled && c.backend == "sim") {
    cfg.sim.camera = {true, c.intrinsics, c.mount, c.format, c.every_frames};
  }

  Section vision = section(root, top, "vision", source);
  const std::string lut = vision.text("lut", "");
  if (!lut.empty()) cfg.vision.lut = std::filesystem::path(lut).is_absolute() ? std::filesystem::path(lut) : base_dir / lut;
  cfg.vision.seed = vision.unsigned_integer("seed", 1);
  cfg.vision.max_trials = vision.integer("max_trials", 30, 1, 10000);
  cfg.vision.skip = vision.integer("skip", 10, 1, 1000);
  vision.reject_unknown();

  Section telemetry = section(root, top, "telemetry", source);
  cfg.trajectory_every = telemetry.integer("trajectory_every", 10, 1, 100000);
  telemetry.reject_unknown();
  if (const std::string why = run_length_problem(cfg, cfg.timeout_s); !why.empty()) {
    if (const toml::node* n = mission.find("timeout_s")) mission.fail(*n, "timeout_s", why);
    mission.fail_missing("timeout_s", why);
  }

  top.reject_unknown();
  cfg.positions = record_positions(root, source);
  return cfg;
}

FirmwareConfig load_config(const std::filesystem::path& path) {
  const hal::FileRead file = hal::read_file(path, "configuration file");
  if (!file.ok()) throw ConfigError(file.error);
  return parse_config(file.bytes, path.string(), path.parent_path());
}

std::string ConfigPositions::at(std::string_view key) const {
  // "executive.tasks[2].name" -> "executive.tasks[2]" -> "executive.tasks" -> "executive" -> file
  while (!key.empty()) {
    if (const auto it = keys.find(key); it != keys.end()) return it->second;
    const auto cut = key.find_last_of(".[");
    key = cut == std::string_view::npos ? std::string_view{} : key.substr(0, cut);
  }
  return file;
}

std::uint64_t trajectory_samples(const FirmwareConfig& config, double seconds) noexcept {
  const double frames = std::ceil(seconds * 1e9 / static_cast<double>(config.executive.period.count()));
  const double samples = std::ceil(frames / std::max(config.trajectory_every, 1)) + 2;
  if (!(samples < 1e18)) return UINT64_MAX;  // also NaN: never cast what does not fit
  return static_cast<std::uint64_t>(samples);
}

std::string run_length_problem(const FirmwareConfig& config, double seconds) {
  std::ostringstream s;
  if (!(std::isfinite(seconds) && seconds > 0.0 && seconds <= kMaxRunSeconds)) {
    s << "must be a number of seconds greater than 0 and at most " << kMaxRunSeconds << ", got " << seconds;
    return s.str();
  }
  const std::uint64_t samples = trajectory_samples(config, seconds);
  if (samples <= kMaxTrajectorySamples) return {};
  const double frames = std::ceil(seconds * 1e9 / static_cast<double>(config.executive.period.count()));
  const auto every = static_cast<long long>(std::ceil(frames / static_cast<double>(kMaxTrajectorySamples - 2)));
  s << "a run of " << seconds << " s records " << samples << " trajectory samples (one every "
    << config.trajectory_every << " frames of " << hal::to_seconds(config.executive.period) * 1e3
    << " ms), more than the " << kMaxTrajectorySamples << " the firmware keeps; shorten the run or set "
    << "telemetry.trajectory_every to at least " << every;
  return s.str();
}

}  // namespace ringlet::firmware
