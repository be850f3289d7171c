#include "incremental.hpp"

#include "mission.hpp"
#include "pool.hpp"
#include "ringlet/planning/experience_file.hpp"

namespace ringlet::experiments {

std::vector<IncrementalChain> run_incremental(const IncrementalPlan& plan, Progress& progress) {
  const std::size_t chains = plan.configs.size();
  progress.begin("incremental learning", chains * (static_cast<std::size_t>(plan.repeats) + 1));
  // One job per chain: its baseline mission, then the repeats in order.
  auto result = run_indexed<IncrementalChain>(chains, plan.threads, [&](std::size_t c) {
    IncrementalChain chain;
    chain.config = plan.configs[c];
    chain.name = chain.config.stem().string();
    MissionSpec spec;
    spec.config = chain.config;
    spec.seed = plan.seed;
    spec.timeout_cap_s = plan.timeout_cap_s;
    const MissionResult base = run_mission(spec);
    chain.baseline_s = base.summary.mission_seconds;
    chain.baseline_complete = base.summary.complete;
    progress.step(chain.name + " baseline");
    std::vector<planning::Experience> learnt;
    const auto model = plan.work_dir / ("incremental_" + chain.name + ".exp");
    spec.learned = true;
    spec.learn_online = true;
    spec.publish_every = 20;  // a new index every 2 s of the mission
    for (int r = 0; r < plan.repeats; ++r) {
      chain.model_size.push_back(learnt.size());
      if (!learnt.empty()) {
        planning::save_experiences(model, learnt);
        spec.experiences = model;
      }
      spec.record = plan.work_dir / ("incremental_" + chain.name + "_" + std::to_string(r) + ".exp");
      const MissionResult run = run_mission(spec);
      chain.seconds.push_back(run.summary.mission_seconds);
      chain.complete.push_back(run.summary.complete);
      learnt.insert(learnt.end(), run.experiences.begin(), run.experiences.end());
      progress.step(chain.name + " repeat " + std::to_string(r + 1));
    }
    return chain;
  });
  progress.end();
  return result;
}

}  // namespace ringlet::experiments
