#include "ringlet/firmware/config.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <cmath>
#include <set>
#include <sstream>

#include <toml++/toml.h>

#include "config_section.hpp"

#include "ringlet/hal/geometry.hpp"
#include "ringlet/firmware/backend_factory.hpp"
#include "ringlet/hal/read_file.hpp"
#include "ringlet/whiteboard/messages.hpp"

namespace ringlet::firmware {
namespace {

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


// One small reader per section. Each read falls back to the setting's current value, so the
// defaults are the structs' (config.hpp).

void read_robot(Section& robot, FirmwareConfig& cfg) {
  cfg.backend = robot.text("backend", cfg.backend, backend_names());
  robot.reject_unknown();
}

void read_executive(Section& exec, FirmwareConfig& cfg, const std::string& file, const toml::source_region& fallback) {
  auto& e = cfg.executive;
  e.period = hal::from_micros(exec.integer("period_us", static_cast<int>(e.period.count() / 1000), 1000, 1000000));
  const bool realtime = cfg.clock == ClockMode::kRealtime;
  cfg.clock = exec.text("clock", realtime ? "realtime" : "lockstep", {"lockstep", "realtime"}) == "realtime"
                  ? ClockMode::kRealtime
                  : ClockMode::kLockstep;
  e.watchdog_periods = exec.integer("watchdog_periods", e.watchdog_periods, 0, 1000);
  e.warn_every_frames = exec.integer("warn_every_frames", e.warn_every_frames, 1, 1000000);
  e.degrade_max_level = exec.integer("degrade_max_level", e.degrade_max_level, 1, 100);
  e.degrade_recover_after = exec.integer("degrade_recover_after", e.degrade_recover_after, 1, 1000000);
  e.overrun_on_cpu_time =
      exec.text("budgets_judged_on", e.overrun_on_cpu_time ? "cpu" : "wall", {"wall", "cpu"}) == "cpu";
  cfg.realtime.fifo_priority = exec.integer("fifo_priority", cfg.realtime.fifo_priority, 0, 99);
  cfg.realtime.lock_memory = exec.boolean("lock_memory", cfg.realtime.lock_memory);
  cfg.realtime.cpu = exec.integer("cpu", cfg.realtime.cpu, -1, 1023);
  read_tasks(exec, cfg, file, fallback);
  exec.reject_unknown();
}

void read_goals(Section& mission, MissionSettings& m) {
  const toml::node* n = mission.find("goals");
  if (n == nullptr) mission.fail_missing("goals", "the mission needs its goals: goals = [[x, y], ...] (m, world frame)");
  const auto* list = n->as_array();
  if (list == nullptr || list->empty()) mission.fail(*n, "goals", "must be a non-empty array of [x, y] pairs");
  if (list->size() > MissionSettings::kMaxGoals) {
    mission.fail(*n, "goals", "has " + std::to_string(list->size()) + " goals; at most " +
                                  std::to_string(MissionSettings::kMaxGoals) + " are allowed");
  }
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::node& g = *list->get(i);
    const auto* pair = g.as_array();
    const auto coordinate = [&](std::size_t k) -> std::optional<double> {
      if (pair == nullptr || pair->size() != 2) return std::nullopt;
      const toml::node& c = *pair->get(k);
      if (const auto* v = c.as_integer()) return static_cast<double>(v->get());
      if (const auto* v = c.as_floating_point(); v != nullptr && std::isfinite(v->get())) return v->get();
      return std::nullopt;
    };
    const auto x = coordinate(0);
    const auto y = coordinate(1);
    if (!x || !y) mission.fail(g, "goals[" + std::to_string(i) + "]", "must be a pair of finite numbers [x, y]");
    m.goals.push_back({*x, *y});
  }
}

void read_mission(Section& mission, MissionSettings& m) {
  const std::string drive = mission.text("drive", "waypoints", {"waypoints", "navigate", "pddl"});
  m.drive = drive == "navigate" ? DriveMode::kNavigate : drive == "pddl" ? DriveMode::kPddl : DriveMode::kWaypoints;
  read_goals(mission, m);
  m.goal_tolerance = mission.number("goal_tolerance_m", m.goal_tolerance, 0.01, 10.0);
  m.timeout_s = mission.number("timeout_s", m.timeout_s, 0.01, kMaxRunSeconds);
  m.ball_tracking = mission.boolean("ball_tracking", m.ball_tracking);
}

void read_follower(Section& follower, behaviour::MoveToWaypointParams& f) {
  f.gain = follower.number("gain", f.gain, 0.0, 100.0);
  f.max_curvature = follower.number("max_curvature", f.max_curvature, 0.01, 100.0);
  f.max_speed = follower.number("max_speed", f.max_speed, 0.01, 20.0);
  f.min_speed = follower.number("min_speed", f.min_speed, 0.0, 20.0);
  f.full_turn_error =
      hal::deg_to_rad(follower.number("full_turn_error_deg", hal::rad_to_deg(f.full_turn_error), 1.0, 180.0));
  f.approach_radius = follower.number("approach_radius_m", f.approach_radius, 0.0, 100.0);
  if (f.min_speed > f.max_speed) {
    if (const toml::node* n = follower.find("min_speed")) follower.fail(*n, "min_speed", "must not exceed max_speed");
    follower.fail_missing("min_speed", "the default min_speed exceeds max_speed; set min_speed");
  }
  follower.reject_unknown();
}

// places = [["p11", 3.0, 3.0], ...]: a place object of the problems and where it is (world, m).
void read_places(Section& pddl, std::vector<pddl::Place>& places) {
  const toml::node* n = pddl.find("places");
  if (n == nullptr) return;
  const toml::array* list = n->as_array();
  if (list == nullptr) pddl.fail(*n, "places", "must be an array of [\"name\", x, y]");
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::node& item = *list->get(i);
    const toml::array* a = item.as_array();
    const std::string key = "places[" + std::to_string(i) + "]";
    const auto number = [&](std::size_t k) -> std::optional<double> {
      const toml::node& c = *a->get(k);
      if (const auto* v = c.as_integer()) return static_cast<double>(v->get());
      if (const auto* v = c.as_floating_point(); v != nullptr && std::isfinite(v->get())) return v->get();
      return std::nullopt;
    };
    if (a == nullptr || a->size() != 3 || a->get(0)->as_string() == nullptr || !number(1) || !number(2)) {
      pddl.fail(item, key, "must be [\"name\", x, y]: a place object and finite coordinates (m)");
    }
    pddl::Place place{a->get(0)->as_string()->get(), *number(1), *number(2)};
    for (char& c : place.name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const pddl::Place& other : places) {
      if (other.name == place.name) pddl.fail(item, key, "place " + place.name + " is listed twice");
    }
    places.push_back(std::move(place));
  }
}

void read_pddl(Section& pddl, PddlSettings& p, const MissionSettings& mission, const behaviour::MoveToWaypointParams& follower,
               const std::filesystem::path& base_dir) {
  p.domain = pddl.path("domain", base_dir);
  p.problems = pddl.path("problems", base_dir);
  read_places(pddl, p.places);
  p.obstacle_radius = pddl.number("obstacle_radius_m", p.obstacle_radius, 0.01, 100.0);
  p.arena_kib = pddl.integer("arena_kib", p.arena_kib, 4, 1 << 20);
  p.max_facts = pddl.integer("max_facts", p.max_facts, 1, 1 << 20);
  p.max_operators = pddl.integer("max_operators", p.max_operators, 1, 1 << 24);
  p.max_nodes = pddl.integer("max_nodes", p.max_nodes, 1, 10000000);
  p.lama_restarts = pddl.integer("lama_restarts", p.lama_restarts, 0, 4);
  p.units_per_slice = pddl.integer("units_per_slice", p.units_per_slice, 1, 1000000);
  p.link.drop = pddl.number("link_drop", p.link.drop, 0.0, 0.9);
  p.link.duplicate = pddl.number("link_duplicate", p.link.duplicate, 0.0, 1.0);
  p.link.max_delay = pddl.integer("link_max_delay", p.link.max_delay, 0, 1000);
  p.link.seed = pddl.unsigned_integer("link_seed", p.link.seed);
  behaviour::PlanExecuteParams& m = p.machine;
  m.planner = pddl.text("planner", m.planner, {"regression", "lama"});
  m.problem = pddl.text("problem", m.problem);
  m.depth = pddl.integer("depth", m.depth, 0, 1000000);
  m.detect_range = pddl.number("detect_range_m", m.detect_range, 0.1, 100.0);
  m.corridor = pddl.number("corridor_m", m.corridor, 0.01, 100.0);
  m.tolerance = mission.goal_tolerance;
  m.follower = follower;
  if (mission.drive == DriveMode::kPddl && m.problem.empty()) {
    pddl.fail_missing("problem", "[mission] drive = \"pddl\" needs the problem the machine loads");
  }
  if (mission.drive == DriveMode::kPddl && p.domain.empty()) {
    pddl.fail_missing("domain", "[mission] drive = \"pddl\" needs a domain file");
  }
  pddl.reject_unknown();
}

void read_planner(Section& planner, PlannerSettings& p, const std::filesystem::path& base_dir) {
  planning::MapConfig& m = p.map;
  m.origin_x = planner.number("origin_x", m.origin_x, -1e5, 1e5);
  m.origin_y = planner.number("origin_y", m.origin_y, -1e5, 1e5);
  m.resolution = planner.number("resolution_m", m.resolution, 0.01, 10.0);
  m.width_cells = planner.integer("width_cells", m.width_cells, 1, 4096);
  m.height_cells = planner.integer("height_cells", m.height_cells, 1, 4096);
  m.region_cells = planner.integer("region_cells", m.region_cells, 1, 256);
  for (const char* key : {"width_cells", "height_cells"}) {
    const int n = std::string_view(key) == "width_cells" ? m.width_cells : m.height_cells;
    if (n % m.region_cells == 0) continue;
    const std::string why = "must be a multiple of region_cells (" + std::to_string(m.region_cells) + "): regions tile the grid";
    if (const toml::node* node = planner.find(key)) planner.fail(*node, key, why);
    planner.fail_missing(key, why);
  }
  p.cost.max_occupied = planner.integer("max_occupied", p.cost.max_occupied, 0, 65536);
  p.cost.top_speed = planner.number("top_speed", p.cost.top_speed, 0.01, 100.0);
  p.pops_per_slice = planner.integer("pops_per_slice", p.pops_per_slice, 1, 1000000);
  const bool knn = p.cost_model == CostModelKind::kKnn;
  p.cost_model = planner.text("cost_model", knn ? "knn" : "binary", {"binary", "knn"}) == "knn" ? CostModelKind::kKnn
                                                                                               : CostModelKind::kBinary;
  p.knn.k = planner.integer("k", p.knn.k, 1, planning::KnnRegressor::kMaxK);
  p.knn.distance_weighted = planner.boolean("distance_weighted", p.knn.distance_weighted);
  p.knn.prior_speed = p.cost.top_speed;
  p.wall_occupied = planner.integer("wall_occupied", p.wall_occupied, 0, 65536);
  p.experiences = planner.path("experiences", base_dir);
  p.prior_map = planner.path("prior_map", base_dir);
  p.record = planner.path("record", base_dir);
  p.capacity = planner.integer("capacity", p.capacity, 1, 10000000);
  p.learn_online = planner.boolean("learn_online", p.learn_online);
  p.publish_every = planner.integer("publish_every", p.publish_every, 1, 1000000);
  // The learned model's keys mean nothing to the binary one: a file that sets them while the
  // binary model plans is probably not what its author thinks it is.
  if (p.cost_model == CostModelKind::kBinary) {
    for (const char* key : {"k", "distance_weighted", "wall_occupied", "experiences", "learn_online", "publish_every"}) {
      if (const toml::node* n = planner.find(key)) planner.fail(*n, key, "applies to cost_model = \"knn\" only");
    }
  }
  planner.reject_unknown();
}

void read_reactive(Section& r, behaviour::reactive::ReactiveParams& p) {
  p.arcs.count = r.integer("arcs", p.arcs.count, 1, behaviour::reactive::kMaxArcs);
  p.arcs.max_curvature = r.number("max_curvature", p.arcs.max_curvature, 0.01, 100.0);
  p.top_speed = r.number("top_speed", p.top_speed, 0.01, 100.0);
  p.robot_radius = r.number("robot_radius_m", p.robot_radius, 0.01, 10.0);
  p.margin = r.number("margin_m", p.margin, 0.0, 10.0);
  p.lookahead = r.number("lookahead_m", p.lookahead, 0.1, 100.0);
  p.waypoint_gain = r.number("waypoint_gain", p.waypoint_gain, 0.01, 100.0);
  p.vote_width = r.number("vote_width", p.vote_width, 0.01, 100.0);
  p.stop_distance = r.number("stop_distance_m", p.stop_distance, 0.0, 100.0);
  p.slow_distance = r.number("slow_distance_m", p.slow_distance, 0.01, 100.0);
  p.congestion_margin = r.number("congestion_margin_m", p.congestion_margin, 0.0, 100.0);
  p.congested_speed = r.number("congested_speed", p.congested_speed, 0.01, 100.0);
  p.max_yaw_rate = r.number("max_yaw_rate", p.max_yaw_rate, 0.01, 100.0);
  for (int b = 0; b < behaviour::reactive::kBehaviours; ++b) {
    const std::string key = std::string("weight_") + behaviour::reactive::kBehaviourNames[static_cast<std::size_t>(b)];
    p.weight[static_cast<std::size_t>(b)] = r.number(key, p.weight[static_cast<std::size_t>(b)], 0.0, 1000.0);
  }
  if (p.slow_distance <= p.stop_distance) {
    if (const toml::node* n = r.find("slow_distance_m")) r.fail(*n, "slow_distance_m", "must be larger than stop_distance_m");
    r.fail_missing("slow_distance_m", "must be larger than stop_distance_m");
  }
  if (p.congested_speed > p.top_speed) {
    if (const toml::node* n = r.find("congested_speed")) r.fail(*n, "congested_speed", "must not exceed top_speed");
    r.fail_missing("congested_speed", "the default congested_speed exceeds top_speed; set congested_speed");
  }
  r.reject_unknown();
}

void read_safety(Section& safety, SafetyParams& p) {
  p.stop_range = safety.number("stop_range_m", p.stop_range, 0.05, 50.0);
  p.release_range = safety.number("release_range_m", p.release_range, 0.05, 50.0);
  p.hold_ms = safety.integer("release_after_ms", static_cast<int>(p.hold_ms), 0, 600000);
  if (p.release_range <= p.stop_range) {
    if (const toml::node* n = safety.find("release_range_m")) {
      safety.fail(*n, "release_range_m", "must be larger than stop_range_m (hysteresis)");
    }
    safety.fail_missing("release_range_m", "must be larger than stop_range_m (hysteresis)");
  }
  safety.reject_unknown();
}

void read_camera(Section& camera, CameraSettings& c) {
  c.backend = camera.text("backend", c.backend, {"robot", "opencv"});
  c.source = camera.text("source", c.source);
  const int width = camera.integer("width", c.intrinsics.width, 16, 4096);
  const int height = camera.integer("height", c.intrinsics.height, 16, 4096);
  if (width % 2 != 0) camera.fail(*camera.find("width"), "width", "must be even (YUYV packs pixel pairs)");
  c.hfov_deg = camera.number("hfov_deg", c.hfov_deg, 1.0, 179.0);
  c.vfov_deg = camera.number("vfov_deg", c.vfov_deg, 1.0, 179.0);
  c.intrinsics = hal::CameraIntrinsics::from_fov(width, height, c.hfov_deg, c.vfov_deg);
  const bool bgr = c.format == hal::PixelFormat::kBgr8;
  c.format = camera.text("format", bgr ? "bgr" : "yuyv", {"yuyv", "bgr"}) == "bgr" ? hal::PixelFormat::kBgr8
                                                                                    : hal::PixelFormat::kYuyv;
  c.mount.pivot_height = camera.number("pivot_height_m", c.mount.pivot_height, 0.01, 10.0);
  c.mount.forward = camera.number("forward_m", c.mount.forward, -1.0, 1.0);
  c.mount.up = camera.number("up_m", c.mount.up, -1.0, 1.0);
  c.mount.pitch = hal::deg_to_rad(camera.number("pitch_deg", hal::rad_to_deg(c.mount.pitch), -15.0, 15.0));
  if (c.backend == "opencv" && c.source.empty()) {
    camera.fail_missing("source", "the \"opencv\" camera needs a source (a device, a video file or an image folder)");
  }
  camera.reject_unknown();
}

void read_vision(Section& vision, VisionSettings& v, const std::filesystem::path& base_dir) {
  v.lut = vision.path("lut", base_dir);
  v.seed = vision.unsigned_integer("seed", v.seed);
  v.max_trials = vision.integer("max_trials", v.max_trials, 1, 10000);
  v.skip = vision.integer("skip", v.skip, 1, 1000);
  v.colour = vision.text("colour", v.lut.empty() ? "adaptive" : "table", {"adaptive", "table"});
  v.ball = vision.text("ball", v.ball, {"orange", "bw"});
  // The models are read and checked when the vision task is made (make_vision), like the table.
  v.ball_model = vision.path("ball_model", base_dir);
  v.robot_model = vision.path("robot_model", base_dir);
  v.robots = vision.boolean("robots", v.robots);
  vision.reject_unknown();
}

void read_field(Section& field, localization::FieldDimensions& d) {
  d.length = field.number("length", d.length, 0.5, 100.0);
  d.width = field.number("width", d.width, 0.5, 100.0);
  d.centre_circle_radius = field.number("centre_circle_radius", d.centre_circle_radius, 0.01, 50.0);
  d.penalty_area_length = field.number("penalty_area_length", d.penalty_area_length, 0.01, 50.0);
  d.penalty_area_width = field.number("penalty_area_width", d.penalty_area_width, 0.01, 100.0);
  d.goal_area_length = field.number("goal_area_length", d.goal_area_length, 0.01, 50.0);
  d.goal_area_width = field.number("goal_area_width", d.goal_area_width, 0.01, 100.0);
  d.penalty_mark_distance = field.number("penalty_mark_distance", d.penalty_mark_distance, 0.01, 50.0);
  d.goal_inner_width = field.number("goal_inner_width", d.goal_inner_width, 0.01, 100.0);
  d.border = field.number("border", d.border, 0.0, 10.0);
  // Each check names its key first ("penalty_area_width must ..."): point at that key.
  if (const std::string why = localization::check(d); !why.empty()) {
    const std::string key = why.substr(0, why.find(' '));
    if (const toml::node* n = field.find(key)) field.fail(*n, key, why);
    field.fail_missing(key, why);
  }
  field.reject_unknown();
}

void read_localization(Section& loc, LocalizationSettings& l) {
  localization::FilterParams& f = l.filter;
  f.particles = loc.integer("particles", f.particles, 10, 5000);
  f.seed = loc.unsigned_integer("seed", f.seed);
  f.observation.line_sigma = loc.number("line_sigma_m", f.observation.line_sigma, 0.01, 2.0);
  f.observation.circle_sigma = loc.number("circle_sigma_m", f.observation.circle_sigma, 0.01, 2.0);
  f.lost_quality = loc.number("lost_quality", f.lost_quality, 0.0, 1.0);
  f.max_reset_share = loc.number("max_reset_share", f.max_reset_share, 0.0, 0.9);
  if (const toml::node* n = loc.find("start")) {
    const auto* a = n->as_array();
    bool numbers = a != nullptr && a->size() == 3;
    for (std::size_t i = 0; numbers && i < 3; ++i) numbers = a->get(i)->is_number();
    if (!numbers) {
      loc.fail(*n, "start", "must be [x, y, heading_deg] (m, m, degrees from +y towards +x)");
    }
    const auto num = [&](std::size_t i) {
      const toml::node& e = *a->get(i);
      return e.is_integer() ? static_cast<double>(e.as_integer()->get()) : e.as_floating_point()->get();
    };
    l.start = hal::Pose2{num(0), num(1), hal::wrap_angle(hal::deg_to_rad(num(2)))};
  }
  l.start_sigma_xy = loc.number("start_sigma_m", l.start_sigma_xy, 0.0, 10.0);
  l.start_sigma_theta = hal::deg_to_rad(loc.number("start_sigma_deg", hal::rad_to_deg(l.start_sigma_theta), 0.0, 180.0));
  const std::string side = loc.text("side", "none", {"west", "east", "none"});
  l.side = side == "west" ? -1.0 : (side == "east" ? 1.0 : 0.0);
  if (const std::string why = localization::check(f); !why.empty()) loc.fail_missing("particles", why);
  loc.reject_unknown();
}

// Type names the schema knows ("FsmStatus", ...), for the [remote] per-type keys.
bool is_message_type(std::string_view name) {
  for (const auto& t : wb::kTypes) {
    if (t.name == name) return true;
  }
  return false;
}

void read_remote(Section& remote, RemoteSettings& r, const std::filesystem::path& base_dir) {
  r.enabled = remote.boolean("enabled", r.enabled);
  r.robot = remote.integer("robot", r.robot, 0, 65535);
  r.domain = remote.integer("domain", r.domain, 0, 232);
  r.partition = remote.text("partition", r.partition);
  if (r.partition.empty() || r.partition.size() > 256) {
    remote.fail(*remote.find("partition"), "partition", "must be 1 to 256 characters");
  }
  r.cyclone_config = remote.path("cyclone_config", base_dir);
  r.poll_ms = remote.integer("poll_ms", r.poll_ms, 1, 1000);
  r.wait_for_monitors = remote.integer("wait_for_monitors", r.wait_for_monitors, 0, 64);
  r.wait_timeout_s = remote.number("wait_timeout_s", r.wait_timeout_s, 0.0, 3600.0);
  if (const toml::node* n = remote.find("max_rate_hz")) {
    const toml::table* t = n->as_table();
    if (t == nullptr) remote.fail(*n, "max_rate_hz", "must be a table of type name = samples per second, e.g. { LaserScan = 10 }");
    for (auto&& [k, v] : *t) {
      const std::string key = "max_rate_hz." + std::string(k.str());
      if (!is_message_type(k.str())) remote.fail(v, key, "no whiteboard type of that name (schema.def)");
      const auto hz = v.value<double>();
      if (!hz || !std::isfinite(*hz) || *hz <= 0.0 || *hz > 100000.0) remote.fail(v, key, "must be a number of samples per second, above 0 and at most 100000");
      r.max_rate_hz[std::string(k.str())] = *hz;
    }
  }
  const auto type_names = [&](const std::string& key, const char* example, std::vector<std::string>& out) {
    const toml::node* n = remote.find(key);
    if (n == nullptr) return;
    const toml::array* a = n->as_array();
    if (a == nullptr) remote.fail(*n, key, std::string("must be an array of type names, e.g. [\"") + example + "\"]");
    for (const toml::node& e : *a) {
      const auto name = e.value<std::string>();
      if (!name) remote.fail(e, key, "must hold type names (strings)");
      if (!is_message_type(*name)) remote.fail(e, key, "no whiteboard type \"" + *name + "\" (schema.def)");
      out.push_back(*name);
    }
  };
  type_names("unpublished", "LaserScan", r.unpublished);
  type_names("accept", "FsmControl", r.accept);
  remote.reject_unknown();
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
  const auto in = [&](const std::string& name) { return section(root, top, name, source); };

  Section robot = in("robot");
  read_robot(robot, cfg);
  Section exec = in("executive");
  read_executive(exec, cfg, source, root.source());
  // Every backend's section is checked when present, so that switching robot.backend never
  // uncovers old typos; only the chosen backend's settings are kept.
  for (const std::string& name : backend_names()) {
    Section backend = in(name);
    auto settings = read_backend_settings(name, backend, base_dir, cfg);
    backend.reject_unknown();
    if (name == cfg.backend) cfg.backend_settings = std::move(settings);
  }
  Section mission = in("mission");
  read_mission(mission, cfg.mission);
  Section follower = in("follower");
  read_follower(follower, cfg.follower);
  Section safety = in("safety");
  read_safety(safety, cfg.safety);
  Section planner = in("planner");
  read_planner(planner, cfg.planner, base_dir);
  Section pddl = in("pddl");
  read_pddl(pddl, cfg.pddl, cfg.mission, cfg.follower, base_dir);
  Section reactive = in("reactive");
  read_reactive(reactive, cfg.reactive);
  Section camera = in("camera");
  read_camera(camera, cfg.camera);
  Section vision = in("vision");
  read_vision(vision, cfg.vision, base_dir);
  Section remote = in("remote");
  read_remote(remote, cfg.remote, base_dir);
  Section field = in("field");
  read_field(field, cfg.localization.field);
  Section loc = in("localization");
  read_localization(loc, cfg.localization);
  Section telemetry = in("telemetry");
  cfg.trajectory_every = telemetry.integer("trajectory_every", cfg.trajectory_every, 1, 100000);
  telemetry.reject_unknown();
  if (const std::string why = run_length_problem(cfg, cfg.mission.timeout_s); !why.empty()) {
    if (const toml::node* n = mission.find("timeout_s")) mission.fail(*n, "timeout_s", why);
    mission.fail_missing("timeout_s", why);
  }
  mission.reject_unknown();

  top.reject_unknown();
  cfg.positions = record_positions(root, source);
  return cfg;
}

const executive::TaskSpec* FirmwareConfig::task(std::string_view name) const noexcept {
  for (const auto& t : tasks) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

std::uint64_t FirmwareConfig::seed() const noexcept {
  if (seed_override) return *seed_override;
  if (backend_settings) return backend_settings->seed().value_or(0);
  return 0;
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
