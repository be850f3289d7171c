#include "data.hpp"

#include <numeric>
#include <stdexcept>
#include <string>

#include "goals.hpp"
#include "pool.hpp"
#include "ringlet/hal/splitmix64.hpp"
#include "ringlet/planning/experience_file.hpp"

namespace ringlet::experiments {
namespace {
constexpr std::uint64_t kSubsetStream = 3000;  // derive_seed indexes of the training subsets
}  // namespace

std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t index) noexcept {
  hal::SplitMix64 g(seed ^ (index * 0xD1B54A32D192ED03ULL));
  (void)g.next();
  return g.next();
}

TrainingData gather_training_data(const DataPlan& plan, Progress& progress) {
  constexpr std::size_t kBatch = 8;   // legs per round: fixed, so the data never depend on the threads
  constexpr std::size_t kMaxLegs = 2000;
  const sim_hal::World world = world_of(plan.config);
  const std::vector<behaviour::Waypoint> goals = random_goals(world, kMaxLegs, derive_seed(plan.seed, 1000));
  TrainingData data;
  progress.begin("data (pb_training)", plan.target);
  std::size_t next = 0;
  while (data.experiences.size() < plan.target) {
    if (next >= kMaxLegs)
      throw std::runtime_error("training data: " + std::to_string(kMaxLegs) + " legs gave only " +
                               std::to_string(data.experiences.size()) + " experiences");
    const std::size_t first = next;
    const auto results = run_indexed<MissionResult>(kBatch, plan.threads, [&](std::size_t j) {
      const std::size_t leg = first + j;
      MissionSpec spec = leg_mission(plan.config, world, goals, leg, plan.work_dir, "training_" + std::to_string(leg));
      spec.seed = derive_seed(plan.seed, 1001 + leg);
      spec.timeout_cap_s = plan.timeout_cap_s;
      spec.record = plan.work_dir / ("training_" + std::to_string(leg) + ".exp");
      return run_mission(spec);
    });
    next += kBatch;
    for (std::size_t j = 0; j < results.size(); ++j) {
      const MissionResult& r = results[j];
      const std::size_t leg = first + j;
      const behaviour::Waypoint from = leg == 0 ? behaviour::Waypoint{world.start.x, world.start.y} : goals[leg - 1];
      MissionRecord m;
      m.goals = 1;
      m.reached = r.summary.goals_reached;
      m.seconds = r.summary.mission_seconds;
      m.straight_m = straight_line_length(from, {goals[leg]});
      m.driven_m = r.summary.distance_m;
      m.experiences = r.experiences.size();
      m.collisions = r.summary.collisions;
      data.missions.push_back(m);
      const std::size_t before = data.experiences.size();
      for (const auto& e : r.experiences) {
        if (data.experiences.size() == plan.target) break;
        data.experiences.push_back(e);
      }
      progress.step("leg " + std::to_string(leg + 1) + (m.reached == 1 ? ": reached" : ": missed"),
                    data.experiences.size() - before);
      if (data.experiences.size() == plan.target) break;
    }
  }
  progress.end();
  return data;
}

std::vector<planning::Experience> seeded_subset(const std::vector<planning::Experience>& data, std::size_t n,
                                                std::uint64_t seed) {
  if (n > data.size())
    throw std::invalid_argument("a subset of " + std::to_string(n) + " from " + std::to_string(data.size()) +
                                " experiences");
  std::vector<std::size_t> order(data.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  hal::SplitMix64 rng(seed);
  for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng.below(i)]);
  std::vector<planning::Experience> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back(data[order[i]]);
  return out;
}

std::vector<planning::Experience> training_subset(const std::vector<planning::Experience>& training, std::size_t n,
                                                  std::uint64_t seed) {
  return seeded_subset(training, n, derive_seed(seed, kSubsetStream + n));
}

std::filesystem::path write_subset(const std::vector<planning::Experience>& training, std::size_t n,
                                   std::uint64_t seed, const std::filesystem::path& dir) {
  const auto path = dir / ("training_n" + std::to_string(n) + ".exp");
  planning::save_experiences(path, training_subset(training, n, seed));
  return path;
}

}  // namespace ringlet::experiments
