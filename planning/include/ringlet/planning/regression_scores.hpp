#pragma once
// The error measures Weka reports for a numeric class (the paper's Tables I and II used Weka):
//   relative absolute error  100 % · Σ|p − a| / Σ|prior − a|, where the prior is what the mean
//                            predictor (ZeroR) would say: in a cross-validation, each fold's
//                            training mean, as Weka's Evaluation sets it per fold
//   correlation              Pearson's r of predictions and actual values (0 when either is
//                            constant, as Weka reports it)
//   mean absolute error      Σ|p − a| / n
//   root mean squared error  √(Σ(p − a)² / n)
// Offline: these allocate nothing but are meant for tools and tests, not the cycle.
#include <cstddef>
#include <span>

namespace ringlet::planning {

struct RegressionScores {
  std::size_t count = 0;
  double relative_absolute_error_pct = 0.0;
  double correlation = 0.0;
  double mean_absolute_error = 0.0;
  double root_mean_squared_error = 0.0;
};

/// Scores predictions against actual values with a prior per instance (the three spans have one
/// length, at least 1; throws std::invalid_argument otherwise).
[[nodiscard]] RegressionScores score_predictions(std::span<const double> predicted, std::span<const double> actual,
                                                 std::span<const double> prior);
/// The same with the mean of `actual` as every instance's prior.
[[nodiscard]] RegressionScores score_predictions(std::span<const double> predicted, std::span<const double> actual);

/// Pearson's correlation coefficient, two-pass (means first); 0 when either side is constant.
[[nodiscard]] double pearson_correlation(std::span<const double> x, std::span<const double> y);

}  // namespace ringlet::planning
