#include "mission.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <toml++/toml.h>

#include "format.hpp"

#include "ringlet/firmware/config.hpp"
#include "ringlet/firmware/mission_runner.hpp"
#include "ringlet/firmware/stack.hpp"

namespace ringlet::experiments {
namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  if (!in) throw std::runtime_error(path.string() + ": cannot read");
  return s.str();
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.close();
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

// `text` with the line that starts with `key` (after blanks) replaced by `line`; throws naming
// `source` when there is no such line.
std::string replace_line(const std::string& text, const std::string& key, const std::string& line,
                         const std::filesystem::path& source) {
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::size_t first = text.find_first_not_of(" \t", at);
    if (first < end && text.compare(first, key.size(), key) == 0)
      return text.substr(0, at) + line + text.substr(end);
    at = end + 1;
  }
  throw std::runtime_error(source.string() + ": no line starting with \"" + key + "\"");
}

// The configuration, on a copy of its world with another start pose when the spec asks for one.
std::filesystem::path configuration_file(const MissionSpec& spec) {
  if (!spec.start) return spec.config;
  toml::table t = toml::parse_file(spec.config.string());
  const auto world_key = t["sim"]["world"].value<std::string>();
  if (!world_key) throw std::runtime_error(spec.config.string() + ": no [sim] world");
  const std::filesystem::path world_file = spec.config.parent_path() / *world_key;
  const auto& p = *spec.start;
  const std::string start = "start " + fixed(p.x, 2) + " " + fixed(p.y, 2) + " " + fixed(p.heading_deg, 0);
  const auto new_world = std::filesystem::absolute(spec.work_dir / (spec.tag + ".world"));
  write_text(new_world, replace_line(read_text(world_file), "start ", start, world_file));
  const auto new_config = spec.work_dir / (spec.tag + ".toml");
  write_text(new_config, replace_line(read_text(spec.config), "world =", "world = \"" + new_world.string() + "\"",
                                      spec.config));
  return new_config;
}

firmware::FirmwareConfig configure(const MissionSpec& spec) {
  firmware::FirmwareConfig cfg = firmware::load_config(configuration_file(spec));
  if (!spec.goals.empty()) {
    if (spec.goals.size() > firmware::MissionSettings::kMaxGoals)
      throw std::invalid_argument("a mission holds at most " + std::to_string(firmware::MissionSettings::kMaxGoals) +
                                  " goals, got " + std::to_string(spec.goals.size()));
    cfg.mission.goals = spec.goals;
  }
  cfg.seed_override = spec.seed;
  cfg.mission.timeout_s = std::min(spec.timeout_s, spec.timeout_cap_s);
  const std::string too_long = firmware::run_length_problem(cfg, cfg.mission.timeout_s);
  if (!too_long.empty())
    throw std::invalid_argument("mission timeout " + std::to_string(cfg.mission.timeout_s) + " s: " + too_long);
  auto& p = cfg.planner;
  p.cost_model = spec.learned ? firmware::CostModelKind::kKnn : firmware::CostModelKind::kBinary;
  p.knn.k = spec.k;
  p.experiences = spec.experiences;
  p.learn_online = spec.learn_online;
  p.publish_every = spec.publish_every;
  p.record = spec.record;
  p.prior_map = spec.prior_map;
  return cfg;
}

}  // namespace

double heading_deg(double ax, double ay, double bx, double by) {
  return std::round(std::atan2(bx - ax, by - ay) * 180.0 / 3.14159265358979323846);
}

MissReport why_missed(const MissionResult& r) {
  MissReport m;
  if (r.summary.complete || r.goals.empty()) return m;
  m.goal = std::min(r.summary.goals_reached, r.goals.size() - 1);
  const auto& t = r.trajectory;
  if (!t.empty()) {
    const hal::Pose2& end = t.back();
    const hal::Pose2& quarter = t[t.size() - 1 - (t.size() - 1) / 4];
    m.to_goal_m = std::hypot(r.goals[m.goal].x - end.x, r.goals[m.goal].y - end.y);
    m.moved_m = std::hypot(end.x - quarter.x, end.y - quarter.y);
  }
  const bool unreachable = std::any_of(r.summary.machines.begin(), r.summary.machines.end(), [](const auto& s) {
    return s.name == "Navigate" && s.state == "Unreachable";
  });
  m.kind = unreachable ? Miss::kUnreachable : m.moved_m < 1.0 ? Miss::kBoxedIn : Miss::kOutOfTime;
  return m;
}

const char* describe(Miss kind) {
  switch (kind) {
    case Miss::kNone: return "reached";
    case Miss::kUnreachable: return "the planner found no way to the goal through the cells the laser had marked (Navigate ended in Unreachable)";
    case Miss::kBoxedIn: return "boxed in: it stopped moving among obstacles";
    case Miss::kOutOfTime: return "still under way when the time limit ran out";
  }
  return "";
}

MissionResult run_mission(const MissionSpec& spec) {
  const firmware::FirmwareConfig cfg = configure(spec);
  firmware::FirmwareStack stack(cfg);
  const std::atomic<bool> interrupt{false};
  std::ostringstream log;  // the narrator's lines: not part of any result
  const firmware::RunOutcome outcome = firmware::run_mission(stack, cfg.mission.timeout_s, interrupt, log);
  if (!outcome.experiences_error.empty()) throw std::runtime_error(outcome.experiences_error);

  MissionResult r;
  r.summary = firmware::summarize(stack, outcome,
                                  stack.executive().failsafe_triggered() || outcome.watchdog_fired);
  const double period_s = hal::to_seconds(cfg.executive.period);
  const auto frames = stack.telemetry().goal_frames();
  r.goal_seconds.assign(cfg.mission.goals.size(), -1.0);
  std::uint64_t last = 0;
  for (std::size_t i = 0; i < frames.size() && i < r.goal_seconds.size(); ++i) {
    r.goal_seconds[i] = static_cast<double>(frames[i] - last) * period_s;
    last = frames[i];
  }
  const auto e = stack.experiences().experiences();
  r.experiences.assign(e.begin(), e.end());
  const auto t = stack.telemetry().trajectory();
  r.trajectory.assign(t.begin(), t.end());
  const hal::PlanPicture plans = stack.telemetry().plan_picture();
  if (!plans.plan_ends.empty()) r.first_plan.assign(plans.plan_points.begin(), plans.plan_points.begin() + plans.plan_ends[0]);
  for (const auto& g : cfg.mission.goals) r.goals.push_back(hal::WorldPoint{g.x, g.y});
  return r;
}

}  // namespace ringlet::experiments
