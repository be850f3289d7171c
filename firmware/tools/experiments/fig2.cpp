#include "fig2.hpp"

#include <algorithm>

#include "data.hpp"
#include "goals.hpp"
#include "mission.hpp"
#include "pool.hpp"
#include "ringlet/planning/paired_t_test.hpp"

namespace ringlet::experiments {
namespace {

constexpr std::uint64_t kGoalStream = 2000;    // derive_seed indexes: the goal sequence
constexpr std::size_t kMaxGoals = 5000;
constexpr std::uint64_t kSimStream = 4000;     // the simulator's seed of leg g

Fig2Row compare(const Fig2System& base, const Fig2System& learned) {
  Fig2Row row;
  row.n = learned.n;
  std::vector<double> a, b;
  for (std::size_t g = 0; g < base.goal_seconds.size(); ++g) {
    if (base.goal_seconds[g] < 0 || learned.goal_seconds[g] < 0) continue;
    a.push_back(base.goal_seconds[g]);
    b.push_back(learned.goal_seconds[g]);
  }
  row.paired = a.size();
  if (row.paired == 0) return row;
  row.baseline_mean_s = row.learned_mean_s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    row.baseline_mean_s += a[i] / static_cast<double>(a.size());
    row.learned_mean_s += b[i] / static_cast<double>(a.size());
  }
  row.improvement_pct = 100.0 * (row.baseline_mean_s - row.learned_mean_s) / row.baseline_mean_s;
  if (row.paired >= 2) {
    const planning::PairedTTest t = planning::paired_t_test(a, b);
    row.t = t.t;
    row.p = t.p_two_sided;
  }
  return row;
}

}  // namespace

Fig2Result run_fig2(const Fig2Plan& plan, Progress& progress) {
  const sim_hal::World world = world_of(plan.config);
  Fig2Result result;
  behaviour::Waypoint at{world.start.x, world.start.y};
  for (const auto& g : random_goals(world, kMaxGoals, derive_seed(plan.seed, kGoalStream))) {
    if (result.straight_m > plan.distance_m) break;
    const double leg = straight_line_length(at, {g});
    result.straight_m += leg;
    result.timeouts.push_back(std::min(leg_timeout(leg), plan.timeout_cap_s));
    result.goals.push_back(g);
    at = g;
  }
  std::vector<std::filesystem::path> files;  // one per system; empty: the baseline
  files.emplace_back();
  for (const std::size_t n : plan.sizes) files.push_back(write_subset(plan.training, n, plan.seed, plan.work_dir));

  const std::size_t legs = result.goals.size(), jobs = files.size() * legs;
  progress.begin("Fig. 2 (pb_test)", jobs);
  const auto runs = run_indexed<MissionResult>(jobs, plan.threads, [&](std::size_t j) {
    const std::size_t s = j / legs, g = j % legs;
    MissionSpec spec = leg_mission(plan.config, world, result.goals, g, plan.work_dir, "fig2_" + std::to_string(j));
    spec.seed = derive_seed(plan.seed, kSimStream + g);  // the same noise for every system
    spec.timeout_cap_s = plan.timeout_cap_s;
    spec.learned = !files[s].empty();
    spec.experiences = files[s];
    MissionResult r = run_mission(spec);
    progress.step((s == 0 ? std::string("baseline") : "n = " + std::to_string(plan.sizes[s - 1])) + ", goal " +
                  std::to_string(g + 1) + (r.summary.complete ? ": reached" : ": missed"));
    return r;
  });
  progress.end();

  for (std::size_t s = 0; s < files.size(); ++s) {
    Fig2System sys;
    sys.n = s == 0 ? 0 : plan.sizes[s - 1];
    sys.name = s == 0 ? "baseline" : "kNN n = " + std::to_string(sys.n);
    for (std::size_t g = 0; g < legs; ++g) {
      const MissionResult& r = runs[s * legs + g];
      sys.goal_seconds.insert(sys.goal_seconds.end(), r.goal_seconds.begin(), r.goal_seconds.end());
      sys.reached += r.summary.goals_reached;
      sys.collisions += r.summary.collisions;
      const Miss why = why_missed(r).kind;
      sys.unreachable += why == Miss::kUnreachable ? 1U : 0U;
      sys.boxed_in += why == Miss::kBoxedIn ? 1U : 0U;
      sys.out_of_time += why == Miss::kOutOfTime ? 1U : 0U;
    }
    result.systems.push_back(std::move(sys));
  }
  for (std::size_t s = 1; s < result.systems.size(); ++s) result.rows.push_back(compare(result.systems[0], result.systems[s]));
  return result;
}

}  // namespace ringlet::experiments
