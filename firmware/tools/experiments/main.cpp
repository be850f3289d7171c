// ringlet-experiments: Powers & Balch §IV reproduced in one command, in lockstep, deterministic
// for a seed, on a small pool of threads (results gathered by index, so the threads never change
// an output byte):
//   1. data     ~5000 experiences in pb_training (random goals, baseline planner, reactive layer)
//   2. Table I  10-fold cross-validation: baseline, kNN k = 2, 5, 15, 50, linear regression, MLP
//   3. Table II kNN k = 5 for n = 100 … 5000
//   4. Fig. 2   pb_test: baseline against each learned model over > 1500 m of goals
//   5. Fig. 3   pb_woods: baseline against learned (n = 5000), plans and trajectories
//   6. incremental learning: repeated missions learning online from an empty model
// Writes docs/results/experiments.md, and CSV and SVG under docs/results/experiments/.
//
// Exit codes: 0 done; 1 a run or an output failed (the message names it); 2 bad flags or input.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include <CLI/CLI.hpp>

#include "data.hpp"
#include "results.hpp"
#include "ringlet/firmware/config.hpp"
#include "ringlet/planning/linear_regression.hpp"
#include "ringlet/planning/knn_regressor.hpp"
#ifdef RINGLET_EXPERIMENTS_MLP
#include <opencv2/core.hpp>

#include "mlp_learner.hpp"
#endif

#ifndef RINGLET_SOURCE_DIR
#define RINGLET_SOURCE_DIR "."
#endif

namespace {

using namespace ringlet;
using namespace ringlet::experiments;

constexpr int kExitOk = 0;
constexpr int kExitFailed = 1;
constexpr int kExitUsage = 2;

std::string command_line(int argc, char** argv) {
  std::string s = "tools/ringlet experiments";
  for (int i = 1; i < argc; ++i) s += std::string(" ") + argv[i];
  return s;
}

std::vector<NamedLearner> table1_learners(const firmware::FirmwareConfig& training) {
  const auto cost = training.planner.cost;
  const int cells = training.planner.map.region_cells * training.planner.map.region_cells;
  std::vector<NamedLearner> l;
  l.push_back({"baseline", [cost, cells] { return std::make_unique<planning::BaselineLearner>(cost, cells); }, 106, -0.44});
  const double paper_err[] = {61, 64, 72, 80}, paper_corr[] = {0.63, 0.65, 0.62, 0.57};
  const int ks[] = {2, 5, 15, 50};
  for (int i = 0; i < 4; ++i) {
    const int k = ks[i];
    l.push_back({"kNN k = " + std::to_string(k),
                 [k] { return std::make_unique<planning::KnnRegressor>(planning::KnnParams{k, false, 0.0}); },
                 paper_err[i], paper_corr[i]});
  }
  l.push_back({"linear regression", [] { return std::make_unique<planning::LinearRegression>(); }, -1, -2});
  return l;
}

void run(Results& r, Progress& progress) {
  const Options& o = r.options;
  const auto work = std::filesystem::temp_directory_path() / ("ringlet-experiments-" + std::to_string(::getpid()));
  std::filesystem::create_directories(work);
  struct Cleanup {
    std::filesystem::path dir;
    ~Cleanup() {
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
    }
  } cleanup{work};
  const auto training_cfg = o.config_dir / "pb_training.toml";
  const firmware::FirmwareConfig training = firmware::load_config(training_cfg);

  r.data = gather_training_data(DataPlan{training_cfg, work, o.experiences, o.seed, o.threads, o.timeout_cap_s}, progress);

  std::vector<NamedLearner> learners = table1_learners(training);
#ifdef RINGLET_EXPERIMENTS_MLP
  cv::setNumThreads(1);  // OpenCV's own threads would make the training order depend on the host
  learners.push_back({"multilayer perceptron", [seed = o.seed] { return std::make_unique<MlpLearner>(seed); }, -1, -2});
#endif
  r.table1 = compare_learners(r.data.experiences, learners, o.folds, o.seed, o.threads, progress, "Table I");
#ifdef RINGLET_EXPERIMENTS_MLP
  r.mlp = r.table1.back();
  r.table1.pop_back();
#endif
  const double paper_err[] = {112, 95, 87, 74, 71, 64}, paper_corr[] = {0.33, 0.43, 0.49, 0.54, 0.56, 0.65};
  const std::size_t paper_n[] = {100, 250, 500, 1000, 2500, 5000};
  std::vector<std::vector<planning::Experience>> subsets;
  for (const std::size_t n : o.sizes) subsets.push_back(training_subset(r.data.experiences, n, o.seed));
  progress.begin("Table II", o.sizes.size());
  for (std::size_t i = 0; i < o.sizes.size(); ++i) {
    NamedLearner knn{"kNN k = 5 (n = " + std::to_string(o.sizes[i]) + ")",
                     [] { return std::make_unique<planning::KnnRegressor>(planning::KnnParams{5, false, 0.0}); }, -1, -2};
    for (std::size_t p = 0; p < 6; ++p)
      if (paper_n[p] == o.sizes[i]) knn.paper_error_pct = paper_err[p], knn.paper_correlation = paper_corr[p];
    Progress silent(true);
    r.table2.push_back(compare_learners(subsets[i], {knn}, o.folds, o.seed, 1, silent, "")[0]);
    progress.step(knn.name);
  }
  progress.end();

  Fig2Plan fig2{o.config_dir / "pb_test.toml", work, r.data.experiences, o.sizes, o.fig2_distance_m, o.seed,
                o.threads, o.timeout_cap_s};
  r.fig2 = run_fig2(fig2, progress);

  const std::size_t largest = *std::max_element(o.sizes.begin(), o.sizes.end());
  Fig3Plan fig3{o.config_dir / "pb_woods.toml", write_subset(r.data.experiences, largest, o.seed, work), largest,
                work, true, o.seed, o.woods_trials, o.threads, o.timeout_cap_s};
  r.fig3 = run_fig3(fig3, progress);
  fig3.prior_map = false;
  r.fig3_laser = run_fig3(fig3, progress);

  r.incremental = run_incremental(
      IncrementalPlan{{o.config_dir / "pb_test.toml", o.config_dir / "pb_woods.toml"}, work, o.repeats, o.seed, o.threads,
                      o.timeout_cap_s},
      progress);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  o.config_dir = std::filesystem::path(RINGLET_SOURCE_DIR) / "firmware" / "config";
  CLI::App app{"Powers & Balch §IV in one command: Tables I and II, Fig. 2, Fig. 3 and incremental learning, in "
               "lockstep, deterministic for --seed. Writes the Markdown report, and CSV and SVG files."};
  bool quick = false;
  app.add_flag("--quick", quick, "small sizes (n ≤ 1000, 300 m of goals, 4 repeats): a few minutes");
  app.add_option("--seed", o.seed, "the one seed of every random choice")->capture_default_str();
  app.add_option("--threads", o.threads, "missions and cross-validations run side by side")
      ->check(CLI::Range(1, 64))->capture_default_str();
  app.add_option("--out", o.out_dir, "CSV, SVG and training data go here")->capture_default_str();
  app.add_option("--markdown", o.markdown, "the report")->capture_default_str();
  app.add_option("--config-dir", o.config_dir, "where pb_training.toml, pb_test.toml and pb_woods.toml are")
      ->check(CLI::ExistingDirectory)->capture_default_str();
  auto* experiences = app.add_option("--experiences", o.experiences, "training experiences to gather (default 5000; --quick 1000)")
      ->check(CLI::Range(std::size_t{20}, std::size_t{100000}));
  auto* sizes = app.add_option("--sizes", o.sizes, "the n of Table II and Fig. 2, each at most --experiences")
      ->delimiter(',');
  auto* distance = app.add_option("--fig2-distance", o.fig2_distance_m, "Fig. 2's goals: straight-line metres, at least (default 1500; --quick 300)")
      ->check(CLI::Range(1.0, 100000.0));
  auto* repeats = app.add_option("--repeats", o.repeats, "incremental learning: missions per world (default 8; --quick 4)")
      ->check(CLI::Range(1, 100));
  auto* trials = app.add_option("--woods-trials", o.woods_trials, "Fig. 3: simulator seeds, the shipped one first (default 5; --quick 2)")
      ->check(CLI::Range(1, 100));
  app.add_option("--mission-timeout", o.timeout_cap_s, "cap every mission's time limit (s): the smoke test's tiny runs")
      ->check(CLI::Range(1.0, 86400.0));
  app.add_option("--folds", o.folds, "cross-validation folds")->check(CLI::Range(2, 100))->capture_default_str();
  app.add_flag("--quiet", o.quiet, "no progress on stderr");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  }
  if (quick) {
    const Options given = o;
    o.make_quick();
    if (experiences->count() > 0) o.experiences = given.experiences;
    if (sizes->count() > 0) o.sizes = given.sizes;
    if (distance->count() > 0) o.fig2_distance_m = given.fig2_distance_m;
    if (repeats->count() > 0) o.repeats = given.repeats;
    if (trials->count() > 0) o.woods_trials = given.woods_trials;
  }
  if (o.sizes.empty()) {
    std::cerr << "ringlet-experiments: --sizes: give at least one n\n";
    return kExitUsage;
  }
  for (const std::size_t n : o.sizes) {
    if (n < static_cast<std::size_t>(o.folds) || n > o.experiences) {
      std::cerr << "ringlet-experiments: --sizes: " << n << " must lie between --folds (" << o.folds
                << ") and --experiences (" << o.experiences << ")\n";
      return kExitUsage;
    }
  }
  for (const char* name : {"pb_training.toml", "pb_test.toml", "pb_woods.toml"}) {
    if (!std::filesystem::is_regular_file(o.config_dir / name)) {
      std::cerr << "ringlet-experiments: --config-dir: " << (o.config_dir / name).string() << " does not exist\n";
      return kExitUsage;
    }
  }
  o.command = command_line(argc, argv);
  Results r;
  r.options = o;
  Progress progress(o.quiet);
  const auto start = std::chrono::steady_clock::now();
  try {
    run(r, progress);
    write_csv_and_plots(r);
    write_report(r);
  } catch (const firmware::ConfigError& e) {
    std::cerr << "ringlet-experiments: " << e.what() << '\n';
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "ringlet-experiments: " << e.what() << '\n';
    return kExitFailed;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cerr << "ringlet-experiments: wrote " << o.markdown.string() << " and " << o.out_dir.string() << "/ in "
            << static_cast<int>(wall) << " s\n";
  return kExitOk;
}
