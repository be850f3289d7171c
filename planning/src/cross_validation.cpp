#include "ringlet/planning/cross_validation.hpp"

#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "ringlet/hal/splitmix64.hpp"

namespace ringlet::planning {
namespace {

/// Uniform in [0, n) without modulo bias: rejects the top partial block of 2^64 (n > 0).
std::uint64_t uniform_below(hal::SplitMix64& rng, std::uint64_t n) {
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() - std::numeric_limits<std::uint64_t>::max() % n;
  std::uint64_t r = rng.next();
  while (r >= limit) r = rng.next();
  return r % n;
}

}  // namespace

std::vector<int> assign_folds(std::size_t n, int folds, std::uint64_t seed) {
  if (folds < 2 || static_cast<std::size_t>(folds) > n)
    throw std::invalid_argument("cross-validation needs 2 to n folds, got " + std::to_string(folds) + " for " +
                                std::to_string(n) + " experiences");
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  hal::SplitMix64 rng(seed);
  for (std::size_t i = n - 1; i > 0; --i) std::swap(order[i], order[uniform_below(rng, i + 1)]);
  std::vector<int> fold(n);
  const std::size_t k = static_cast<std::size_t>(folds), base = n / k, extra = n % k;
  std::size_t pos = 0;
  for (std::size_t f = 0; f < k; ++f) {
    const std::size_t size = base + (f < extra ? 1 : 0);
    for (std::size_t j = 0; j < size; ++j) fold[order[pos++]] = static_cast<int>(f);
  }
  return fold;
}

CrossValidation cross_validate(std::span<const Experience> data, int folds, std::uint64_t seed,
                               const LearnerFactory& make) {
  CrossValidation cv;
  cv.fold = assign_folds(data.size(), folds, seed);
  cv.predicted.assign(data.size(), 0.0);
  cv.prior.assign(data.size(), 0.0);
  std::vector<Experience> train;
  train.reserve(data.size());
  for (int f = 0; f < folds; ++f) {
    train.clear();
    double sum = 0.0;
    for (std::size_t i = 0; i < data.size(); ++i) {
      if (cv.fold[i] == f) continue;
      train.push_back(data[i]);
      sum += data[i].achieved_speed;
    }
    const double train_mean = sum / static_cast<double>(train.size());
    const std::unique_ptr<SpeedLearner> learner = make();
    learner->fit(train);
    for (std::size_t i = 0; i < data.size(); ++i) {
      if (cv.fold[i] != f) continue;
      cv.predicted[i] = learner->predict(data[i].features);
      cv.prior[i] = train_mean;
    }
  }
  std::vector<double> actual(data.size());
  for (std::size_t i = 0; i < data.size(); ++i) actual[i] = data[i].achieved_speed;
  cv.scores = score_predictions(cv.predicted, actual, cv.prior);
  return cv;
}

}  // namespace ringlet::planning
