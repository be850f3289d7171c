#include "ringlet/planning/regression_scores.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace ringlet::planning {
namespace {

double mean(std::span<const double> v) {
  double sum = 0.0;
  for (const double x : v) sum += x;
  return sum / static_cast<double>(v.size());
}

void require_same_nonzero_length(std::size_t a, std::size_t b, const char* what) {
  if (a != b || a == 0)
    throw std::invalid_argument(std::string(what) + ": need equal, non-zero lengths, got " + std::to_string(a) +
                                " and " + std::to_string(b));
}

}  // namespace

double pearson_correlation(std::span<const double> x, std::span<const double> y) {
  require_same_nonzero_length(x.size(), y.size(), "pearson_correlation");
  const double mx = mean(x), my = mean(y);
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double dx = x[i] - mx, dy = y[i] - my;
    sxy += dx * dy;
    sxx += dx * dx;
    syy += dy * dy;
  }
  return sxx > 0.0 && syy > 0.0 ? sxy / std::sqrt(sxx * syy) : 0.0;
}

RegressionScores score_predictions(std::span<const double> predicted, std::span<const double> actual,
                                   std::span<const double> prior) {
  require_same_nonzero_length(predicted.size(), actual.size(), "score_predictions");
  require_same_nonzero_length(prior.size(), actual.size(), "score_predictions (prior)");
  double abs_err = 0.0, sq_err = 0.0, prior_abs_err = 0.0;
  for (std::size_t i = 0; i < actual.size(); ++i) {
    const double e = predicted[i] - actual[i];
    abs_err += std::abs(e);
    sq_err += e * e;
    prior_abs_err += std::abs(prior[i] - actual[i]);
  }
  const auto n = static_cast<double>(actual.size());
  RegressionScores s;
  s.count = actual.size();
  // A perfectly constant target leaves nothing to be relative to: Weka prints NaN, so do we.
  s.relative_absolute_error_pct = prior_abs_err > 0.0 ? 100.0 * abs_err / prior_abs_err : std::nan("");
  s.correlation = pearson_correlation(predicted, actual);
  s.mean_absolute_error = abs_err / n;
  s.root_mean_squared_error = std::sqrt(sq_err / n);
  return s;
}

RegressionScores score_predictions(std::span<const double> predicted, std::span<const double> actual) {
  require_same_nonzero_length(predicted.size(), actual.size(), "score_predictions");
  const std::vector<double> prior(actual.size(), mean(actual));
  return score_predictions(predicted, actual, prior);
}

}  // namespace ringlet::planning
