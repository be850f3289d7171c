#pragma once
// Step 1 of the experiments (Powers & Balch §IV-A): experiences gathered in the training world by
// the baseline planner and the reactive layer driving a chain of seeded random goals, each leg a
// mission of its own (goals.hpp, leg_mission). Legs run in batches of a fixed size on the pool
// until the target is reached; the experiences are concatenated in leg order and cut to the
// target (the legs after the one that reached it are dropped), so the set does not depend on the
// threads.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "mission.hpp"
#include "progress.hpp"

namespace ringlet::experiments {

struct DataPlan {
  std::filesystem::path config;   // the training world's configuration
  std::filesystem::path work_dir; // each mission's experience file (the planner records to a file)
  std::size_t target = 5000;      // experiences wanted
  std::uint64_t seed = 1;
  int threads = 2;
  double timeout_cap_s = 86400.0;
};

struct MissionRecord {      // one leg, for the report
  std::size_t goals = 0, reached = 0;
  double seconds = 0.0, straight_m = 0.0, driven_m = 0.0;
  std::size_t experiences = 0;
  std::uint64_t collisions = 0;
};

struct TrainingData {
  std::vector<planning::Experience> experiences;  // exactly `target`, in mission order
  std::vector<MissionRecord> missions;  // the legs run, in order
};

[[nodiscard]] TrainingData gather_training_data(const DataPlan& plan, Progress& progress);

/// The seed of sub-task `index` of a run seeded `seed` (splitmix64 of both): every mission, goal
/// list and subset draws its own.
[[nodiscard]] std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t index) noexcept;

/// The first n of a seeded shuffle of `data` (subsets of one shuffle are nested: n = 100 lies
/// inside n = 250). n ≤ data.size().
[[nodiscard]] std::vector<planning::Experience> seeded_subset(const std::vector<planning::Experience>& data,
                                                              std::size_t n, std::uint64_t seed);

/// The model of n experiences the experiments use (Table II, Fig. 2, Fig. 3): a seeded subset
/// with a seed of its own for each n.
[[nodiscard]] std::vector<planning::Experience> training_subset(const std::vector<planning::Experience>& training,
                                                                std::size_t n, std::uint64_t seed);

/// Writes training_subset(training, n, seed) to dir/training_n<n>.exp and returns the path: the model
/// file a learned planner loads ([planner] experiences). Each n draws from its own seed.
[[nodiscard]] std::filesystem::path write_subset(const std::vector<planning::Experience>& training, std::size_t n,
                                                 std::uint64_t seed, const std::filesystem::path& dir);

}  // namespace ringlet::experiments
