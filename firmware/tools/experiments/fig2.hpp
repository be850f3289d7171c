#pragma once
// Fig. 2 of Powers & Balch (§IV-B): in the test world, the baseline planner against the planner
// with a kNN (k = 5) model trained on n experiences of the training world, for each n, over one
// seeded sequence of goals of more than `distance_m` straight-line metres. Each leg (previous goal
// to goal) is a mission of its own (goals.hpp, leg_mission), with the same simulator seed for
// every system, run as independent jobs; a goal's time is its leg's mission time. Per n: the average time
// per goal over the goals both systems reached, the improvement in %, and the paired t-test over
// those per-goal times. A goal a system missed is counted and reported, never dropped silently.
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "progress.hpp"
#include "ringlet/behaviour/move_to_waypoint.hpp"
#include "ringlet/planning/experience.hpp"

namespace ringlet::experiments {

struct Fig2Plan {
  std::filesystem::path config;    // the test world's configuration
  std::filesystem::path work_dir;  // the models' experience files
  std::vector<planning::Experience> training;  // the training world's data (subsets drawn from it)
  std::vector<std::size_t> sizes;
  double distance_m = 1500.0;
  std::uint64_t seed = 1;
  int threads = 2;
  double timeout_cap_s = 86400.0;
};

struct Fig2System {
  std::string name;                  // "baseline", "kNN n = 100", ...
  std::size_t n = 0;                 // training experiences (0: the baseline)
  std::vector<double> goal_seconds;  // per goal of the sequence; -1: missed
  std::size_t reached = 0;
  std::uint64_t collisions = 0;
  std::size_t unreachable = 0, boxed_in = 0, out_of_time = 0;  // the missed goals, by why_missed
};

struct Fig2Row {                     // a learned system against the baseline
  std::size_t n = 0;
  std::size_t paired = 0;            // goals both reached
  // NaN where too few goals were paired (none for the means, fewer than two for the test).
  double baseline_mean_s = std::numeric_limits<double>::quiet_NaN(), learned_mean_s = baseline_mean_s;
  double improvement_pct = baseline_mean_s;  // (baseline − learned) / baseline · 100
  double t = baseline_mean_s, p = baseline_mean_s;  // paired t-test, two-sided
};

struct Fig2Result {
  std::vector<behaviour::Waypoint> goals;       // the whole sequence
  std::vector<double> timeouts;                 // each leg's time limit
  double straight_m = 0;                        // its straight-line length from the world's start
  std::vector<Fig2System> systems;              // baseline first
  std::vector<Fig2Row> rows;                    // one per n
};

[[nodiscard]] Fig2Result run_fig2(const Fig2Plan& plan, Progress& progress);

}  // namespace ringlet::experiments
