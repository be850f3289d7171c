#pragma once
// Incremental learning (the paper's title): one mission repeated, the planner learning online
// ([planner] learn_online) from an empty model. Repeat r starts with every experience the repeats
// before it recorded (loaded with [planner] experiences) and adds its own during the mission.
// Each chain (a world's mission) is a sequence; the chains and the baseline references run on the
// pool side by side.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "progress.hpp"

namespace ringlet::experiments {

struct IncrementalChain {
  std::string name;                   // "pb_test", "pb_woods"
  std::filesystem::path config;
  double baseline_s = 0;              // the binary planner's mission time
  bool baseline_complete = false;
  std::vector<double> seconds;        // per repeat
  std::vector<bool> complete;
  std::vector<std::size_t> model_size;  // experiences loaded at the start of each repeat
};

struct IncrementalPlan {
  std::vector<std::filesystem::path> configs;
  std::filesystem::path work_dir;
  int repeats = 8;
  std::uint64_t seed = 1;
  int threads = 2;
  double timeout_cap_s = 86400.0;
};

[[nodiscard]] std::vector<IncrementalChain> run_incremental(const IncrementalPlan& plan, Progress& progress);

}  // namespace ringlet::experiments
