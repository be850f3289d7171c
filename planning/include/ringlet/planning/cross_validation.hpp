#pragma once
// k-fold cross-validation as the paper's Tables I and II report it (Weka's): the data are shuffled
// by a seeded generator and cut into k folds of sizes differing by at most one; each fold is
// predicted by a learner fitted on the other k − 1, and the scores pool every fold's predictions,
// each relative to its own training fold's mean (regression_scores.hpp). Deterministic for a seed,
// the same on every host (splitmix64 and an unbiased Fisher–Yates shuffle written here, not the
// standard library's implementation-defined distributions). Offline: allocates freely.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "ringlet/planning/regression_scores.hpp"
#include "ringlet/planning/speed_learner.hpp"

namespace ringlet::planning {

using LearnerFactory = std::function<std::unique_ptr<SpeedLearner>()>;

struct CrossValidation {
  RegressionScores scores;
  std::vector<int> fold;            // per experience, in input order
  std::vector<double> predicted;    // per experience, by the learner that did not see it
  std::vector<double> prior;        // per experience, the mean label of its training folds
};

/// The fold (0 … folds − 1) of each of n items: a seeded shuffle cut into contiguous blocks, the
/// first n mod folds blocks one larger. Needs 2 ≤ folds ≤ n (throws std::invalid_argument).
[[nodiscard]] std::vector<int> assign_folds(std::size_t n, int folds, std::uint64_t seed);

/// `folds`-fold cross-validation of the learners `make` builds (a fresh one per fold).
[[nodiscard]] CrossValidation cross_validate(std::span<const Experience> data, int folds, std::uint64_t seed,
                                             const LearnerFactory& make);

}  // namespace ringlet::planning
