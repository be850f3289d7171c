#include "goals.hpp"

#include <cmath>
#include <stdexcept>

#include <toml++/toml.h>

#include "ringlet/hal/splitmix64.hpp"
#include "ringlet/sim_hal/collision.hpp"

namespace ringlet::experiments {
namespace {

// A coordinate on a 5 cm lattice inside [lo, hi]: exact in binary, so the goals print and compare
// the same everywhere.
double lattice(hal::SplitMix64& rng, double lo, double hi) {
  const auto steps = static_cast<std::uint64_t>(std::floor((hi - lo) * 20.0));
  return lo + static_cast<double>(rng.below(steps + 1)) / 20.0;
}

}  // namespace

std::vector<behaviour::Waypoint> random_goals(const sim_hal::World& world, std::size_t count, std::uint64_t seed,
                                              const GoalRules& rules) {
  hal::SplitMix64 rng(seed);
  std::vector<behaviour::Waypoint> goals;
  behaviour::Waypoint last{world.start.x, world.start.y};
  constexpr int kTries = 100000;
  while (goals.size() < count) {
    int tries = 0;
    for (;; ++tries) {
      if (tries == kTries)
        throw std::runtime_error("world \"" + world.name + "\": no free goal found in " + std::to_string(kTries) +
                                 " tries (clearance " + std::to_string(rules.clearance) + " m)");
      const behaviour::Waypoint g{lattice(rng, world.min.x, world.max.x), lattice(rng, world.min.y, world.max.y)};
      if (std::hypot(g.x - last.x, g.y - last.y) < rules.min_leg) continue;
      if (sim_hal::disc_collides(world, sim_hal::Vec2{g.x, g.y}, rules.clearance)) continue;
      goals.push_back(g);
      last = g;
      break;
    }
  }
  return goals;
}

double straight_line_length(behaviour::Waypoint from, const std::vector<behaviour::Waypoint>& goals) {
  double sum = 0.0;
  for (const auto& g : goals) {
    sum += std::hypot(g.x - from.x, g.y - from.y);
    from = g;
  }
  return sum;
}

MissionSpec leg_mission(const std::filesystem::path& config, const sim_hal::World& world,
                        const std::vector<behaviour::Waypoint>& goals, std::size_t i,
                        const std::filesystem::path& work_dir, const std::string& tag) {
  const behaviour::Waypoint origin{world.start.x, world.start.y};
  const behaviour::Waypoint from = i == 0 ? origin : goals[i - 1];
  const behaviour::Waypoint before = i < 2 ? origin : goals[i - 2];
  MissionSpec spec;
  spec.config = config;
  spec.goals = {goals[i]};
  spec.timeout_s = leg_timeout(std::hypot(goals[i].x - from.x, goals[i].y - from.y));
  if (i > 0) spec.start = MissionSpec::Start{from.x, from.y, heading_deg(before.x, before.y, from.x, from.y)};
  spec.work_dir = work_dir;
  spec.tag = tag;
  return spec;
}

double leg_timeout(double straight_m) noexcept { return 30.0 + 4.0 * straight_m; }

sim_hal::World world_of(const std::filesystem::path& config) {
  toml::table t;
  try {
    t = toml::parse_file(config.string());
  } catch (const toml::parse_error& e) {
    throw std::runtime_error(config.string() + ": " + std::string(e.description()));
  }
  const auto world = t["sim"]["world"].value<std::string>();
  if (!world) throw std::runtime_error(config.string() + ": no [sim] world");
  return sim_hal::load_world(config.parent_path() / *world);
}

}  // namespace ringlet::experiments
