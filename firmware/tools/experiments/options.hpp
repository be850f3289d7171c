#pragma once
// What one run of ringlet-experiments does: sizes, seeds and where the outputs go. The defaults
// are the paper's full experiment; quick() shrinks them to minutes.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace ringlet::experiments {

struct Options {
  std::filesystem::path config_dir;           // pb_training.toml, pb_test.toml, pb_woods.toml
  std::filesystem::path out_dir = "docs/results/experiments";  // CSV, SVG and the training data
  std::filesystem::path markdown = "docs/results/experiments.md";
  std::uint64_t seed = 1;
  int threads = 2;
  bool quick = false;
  bool quiet = false;
  std::size_t experiences = 5000;                                    // step 1
  int folds = 10;                                                    // Tables I and II
  std::vector<std::size_t> sizes{100, 250, 500, 1000, 2500, 5000};  // Table II and Fig. 2
  double fig2_distance_m = 1500.0;   // Fig. 2: the goal sequence's straight-line length, at least
  int repeats = 8;                   // incremental learning: missions per chain
  int woods_trials = 5;              // Fig. 3: simulator seeds (the shipped one first)
  double timeout_cap_s = 86400.0;    // every mission's time limit at most this (the smallest runs)
  std::string command;               // the command line, for the report

  /// --quick: n up to 1000, a 300 m goal sequence, 4 repeats, 2 woods trials.
  void make_quick() {
    quick = true;
    experiences = 1000;
    sizes = {100, 250, 500, 1000};
    fig2_distance_m = 300.0;
    repeats = 4;
    woods_trials = 2;
  }
};

}  // namespace ringlet::experiments
