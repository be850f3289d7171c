#pragma once
// Tables I and II of Powers & Balch (§IV-A): seeded 10-fold cross-validation of the learners on
// the training world's experiences, scored as Weka scores them (relative absolute error against
// each fold's training mean, Pearson correlation). Each cross-validation is one job on the pool.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "progress.hpp"
#include "ringlet/planning/cross_validation.hpp"

namespace ringlet::experiments {

struct LearnerRow {
  std::string name;            // "kNN k = 5", ...
  std::size_t n = 0;           // experiences cross-validated
  planning::RegressionScores scores;
  double paper_error_pct = -1; // the paper's figure (-1: none given)
  double paper_correlation = -2;
};

struct NamedLearner {
  std::string name;
  planning::LearnerFactory make;
  double paper_error_pct = -1;
  double paper_correlation = -2;
};

/// One row per learner, in order: `folds`-fold cross-validation of each over `data`.
[[nodiscard]] std::vector<LearnerRow> compare_learners(const std::vector<planning::Experience>& data,
                                                       const std::vector<NamedLearner>& learners, int folds,
                                                       std::uint64_t seed, int threads, Progress& progress,
                                                       const std::string& phase);

}  // namespace ringlet::experiments
