#pragma once
// Fig. 3 of Powers & Balch (§IV-C): the path in the woods, the baseline planner against the
// learned one (kNN, k = 5, on the training world's n experiences): each system's first plan and
// its trajectory, and the mission times. The paper shows one trial; here the trial with the
// shipped configuration's simulator seed is the figure, and more seeds show how much one trial
// says. Powers & Balch's planner knew the woods' obstacles ("obstacles in the map are shown in
// black"): the figure's runs give the planner the world as a prior map (ringlet-world-map's
// map); the same trials with the laser alone are reported beside them (a robot that discovers the
// trees as it drives can get boxed in among them with either model).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "mission.hpp"
#include "progress.hpp"

namespace ringlet::experiments {

struct Fig3Plan {
  std::filesystem::path config;       // pb_woods.toml
  std::filesystem::path experiences;  // the learned model's file
  std::size_t n = 0;                  // how many it holds
  std::filesystem::path work_dir;     // where the prior map is written
  bool prior_map = true;              // the planner is given the world's obstacles (else: laser only)
  std::uint64_t seed = 1;
  int trials = 5;                     // simulator seeds: the configuration's, then derived ones
  int threads = 2;
  double timeout_cap_s = 86400.0;
};

struct Fig3Trial {
  std::uint64_t sim_seed = 0;
  MissionResult baseline, learned;
  double cut_pct = 0;   // (baseline − learned) / baseline mission time · 100; NaN unless both complete
  double plan_length_baseline_m = 0, plan_length_learned_m = 0;  // the first plans' lengths
};

struct Fig3Result {
  std::size_t n = 0;
  bool prior_map = true;
  std::vector<Fig3Trial> trials;   // the first is the figure
  double mean_cut_pct = 0;         // over the trials both completed (NaN: none)
  std::size_t both_complete = 0;
};

[[nodiscard]] Fig3Result run_fig3(const Fig3Plan& plan, Progress& progress);

/// The prior map of `config`'s simulated world (what ringlet-world-map writes), as `dir`/name.map.
[[nodiscard]] std::filesystem::path write_prior_map(const std::filesystem::path& config, const std::filesystem::path& dir);

/// The four panels as one SVG: (a) the baseline's first plan, (b) its trajectory, (c) the learned
/// model's first plan, (d) its trajectory, over the woods.
void write_fig3_svg(const std::filesystem::path& path, const std::filesystem::path& config, const Fig3Result& r);

}  // namespace ringlet::experiments
