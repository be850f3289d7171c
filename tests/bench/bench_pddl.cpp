// The PDDL planners on the shipped domains: for each problem and planner, a whole search run
// in slices of a fixed budget of work units (expansions), as the planner task would run it.
// Reported: expansions, slices, the plan's length, and the per-slice cost (mean and largest
// thread CPU time of one slice, against its budget in units: on 2 shared cores wall time
// measures the neighbours).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>
#include <memory>
#include <string>

#include "ringlet/pddl/grounder.hpp"
#include "ringlet/pddl/lama_planner.hpp"
#include "ringlet/pddl/loader.hpp"
#include "ringlet/pddl/regression_planner.hpp"

namespace {

using namespace ringlet::pddl;

constexpr std::uint32_t kBudget = 100;  // expansions per slice

double thread_cpu_us() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e6 + static_cast<double>(t.tv_nsec) * 1e-3;
}

struct Loaded {
  LoadedFiles files;
  std::unique_ptr<Arena> arena;
  Task task;
};

Loaded load(const std::string& domain, const std::string& problem) {
  const std::string dir = std::string(RINGLET_PDDL_DOMAINS_DIR) + "/" + domain + "/";
  auto l = load_files(dir + "domain.pddl", dir + problem);
  Loaded out{std::move(std::get<LoadedFiles>(l)), std::make_unique<Arena>(std::size_t{16} << 20U), {}};
  out.task = ground(out.files.domain, out.files.problem, *out.arena).task;
  return out;
}

template <typename P>
void search(benchmark::State& state, const char* domain, const char* problem) {
  const Loaded l = load(domain, problem);
  P planner(PlannerLimits::for_task(l.task, 500000));
  double slice_max_cpu_us = 0.0;
  double slice_total_cpu_us = 0.0;
  for (auto _ : state) {
    PlannerStatus s = planner.start(l.task, kNoHorizon);
    while (s == PlannerStatus::kRunning) {
      const double t0 = thread_cpu_us();
      s = planner.step(kBudget);
      const double us = thread_cpu_us() - t0;
      slice_max_cpu_us = std::max(slice_max_cpu_us, us);
      slice_total_cpu_us += us;
    }
    if (s != PlannerStatus::kFound) state.SkipWithError(planner.reason());
  }
  const PlannerStats& st = planner.stats();
  state.counters["expansions"] = static_cast<double>(st.expansions);
  state.counters["first_plan_exp"] = static_cast<double>(st.first_plan_expansions);
  state.counters["plan_len"] = st.plan_length;
  state.counters["slices"] = static_cast<double>(st.slices);
  state.counters["budget_units"] = kBudget;
  state.counters["slice_mean_cpu_us"] = slice_total_cpu_us / (static_cast<double>(st.slices) * static_cast<double>(state.iterations()));
  state.counters["slice_max_cpu_us"] = slice_max_cpu_us;
}

void lama(benchmark::State& s, const char* d, const char* p) { search<LamaPlanner>(s, d, p); }
void regression(benchmark::State& s, const char* d, const char* p) { search<RegressionPlanner>(s, d, p); }

BENCHMARK_CAPTURE(regression, gripper_p02, "gripper", "p02.pddl")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lama, gripper_p02, "gripper", "p02.pddl")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lama, gripper_p08, "gripper", "p08.pddl")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(regression, blocksworld_p01, "blocksworld", "p01.pddl")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lama, blocksworld_p01, "blocksworld", "p01.pddl")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lama, blocksworld_p03, "blocksworld", "p03.pddl")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(regression, logistics_p02, "logistics", "p02.pddl")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lama, logistics_p02, "logistics", "p02.pddl")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(regression, navigation_p03, "navigation", "p03.pddl")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lama, navigation_p03, "navigation", "p03.pddl")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lama, briefcase_p02, "briefcase", "p02.pddl")->Unit(benchmark::kMillisecond);

}  // namespace
BENCHMARK_MAIN();
