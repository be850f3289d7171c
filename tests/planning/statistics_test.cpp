// Weka's scores, cross-validation with a known answer, and the paired t-test against scipy.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "ringlet/hal/splitmix64.hpp"
#include "ringlet/planning/cross_validation.hpp"
#include "ringlet/planning/knn_regressor.hpp"
#include "ringlet/planning/linear_regression.hpp"
#include "ringlet/planning/paired_t_test.hpp"

namespace ringlet::planning {
namespace {

TEST(RegressionScores, HandComputedValues) {
  const std::vector<double> actual{1.0, 2.0, 3.0, 4.0};  // mean 2.5: Σ|prior − a| = 4
  const std::vector<double> predicted{1.5, 2.0, 2.0, 4.5};  // errors 0.5, 0, −1, 0.5
  const RegressionScores s = score_predictions(predicted, actual);
  EXPECT_EQ(s.count, 4U);
  EXPECT_DOUBLE_EQ(s.relative_absolute_error_pct, 100.0 * 2.0 / 4.0);
  EXPECT_DOUBLE_EQ(s.mean_absolute_error, 0.5);
  EXPECT_DOUBLE_EQ(s.root_mean_squared_error, std::sqrt(1.5 / 4.0));
  // r = Σ dp·da / √(Σdp² Σda²): dp = −1, −0.5, −0.5, 2 (mean 2.5), da = −1.5, −0.5, 0.5, 1.5.
  EXPECT_DOUBLE_EQ(s.correlation, (1.5 + 0.25 - 0.25 + 3.0) / std::sqrt(5.5 * 5.0));
  const std::vector<double> constant(4, 2.0);
  EXPECT_EQ(score_predictions(constant, actual).correlation, 0.0);  // as Weka: no variance, no correlation
  EXPECT_TRUE(std::isnan(score_predictions(actual, constant).relative_absolute_error_pct));
  EXPECT_THROW((void)score_predictions(std::vector<double>{1.0}, actual), std::invalid_argument);
}

TEST(CrossValidation, FoldsAreBalancedAndFollowTheSeed) {
  const auto a = assign_folds(103, 10, 42);
  std::vector<int> sizes(10, 0);
  for (const int f : a) ++sizes[static_cast<std::size_t>(f)];
  for (int f = 0; f < 10; ++f) EXPECT_EQ(sizes[static_cast<std::size_t>(f)], f < 3 ? 11 : 10);
  EXPECT_EQ(assign_folds(103, 10, 42), a);
  EXPECT_NE(assign_folds(103, 10, 43), a);
  EXPECT_THROW((void)assign_folds(5, 10, 1), std::invalid_argument);
  EXPECT_THROW((void)assign_folds(5, 1, 1), std::invalid_argument);
}

std::vector<Experience> synthetic(std::size_t n, double noise, std::uint64_t seed) {
  hal::SplitMix64 rng(seed);
  auto unit = [&] { return static_cast<double>(rng.next() >> 11) * 0x1p-53; };
  std::vector<Experience> out(n);
  for (Experience& e : out) {
    for (double& f : e.features) f = unit();
    e.features[kDiagonal] = static_cast<double>(rng.below(2));
    e.achieved_speed = 2.0 - 1.2 * e.features[kTo] - 0.5 * e.features[kFromLeft] + 0.3 * e.features[kDiagonal] +
                       noise * (unit() - 0.5);
  }
  return out;
}

TEST(CrossValidation, LinearRegressionOnALinearLawIsExact) {
  const auto data = synthetic(400, 0.0, 1);
  const CrossValidation cv = cross_validate(data, 10, 42, [] { return std::make_unique<LinearRegression>(); });
  EXPECT_LT(cv.scores.relative_absolute_error_pct, 1e-9);
  EXPECT_NEAR(cv.scores.correlation, 1.0, 1e-12);
  EXPECT_LT(cv.scores.root_mean_squared_error, 1e-12);
  EXPECT_EQ(cv.scores.count, data.size());
}

TEST(CrossValidation, TheMeanPredictorScoresOneHundredPercent) {
  const auto data = synthetic(250, 0.3, 2);
  const CrossValidation cv = cross_validate(data, 10, 7, [] { return std::make_unique<MeanLearner>(); });
  // Each prediction is its training fold's mean, the very prior Weka divides by.
  EXPECT_NEAR(cv.scores.relative_absolute_error_pct, 100.0, 1e-9);
  for (std::size_t i = 0; i < data.size(); ++i) EXPECT_EQ(cv.predicted[i], cv.prior[i]);
}

TEST(CrossValidation, KnnLearnsANoisyLawAndIsDeterministic) {
  const auto data = synthetic(1000, 0.2, 3);
  auto knn = [] { return std::make_unique<KnnRegressor>(KnnParams{.k = 5}); };
  const CrossValidation a = cross_validate(data, 10, 42, knn), b = cross_validate(data, 10, 42, knn);
  EXPECT_EQ(a.predicted, b.predicted);
  EXPECT_LT(a.scores.relative_absolute_error_pct, 80.0);  // better than the mean, worse than exact
  EXPECT_GT(a.scores.relative_absolute_error_pct, 20.0);
  EXPECT_GT(a.scores.correlation, 0.6);
}

// Expected values from scipy 1.10.1 (python3-scipy, Debian 12), computed once with:
//   python3 -c "from scipy import stats; print(stats.ttest_rel(A, B))"
// for each pair (A, B) below, and for the functions
//   python3 -c "from scipy import special; print(special.betainc(a, b, x))"
//   python3 -c "from scipy import stats; print(stats.t.cdf(t, df))"
// (tests/planning/t_test_scipy.py recomputes them all when scipy is present.)
struct TTestCase {
  std::vector<double> a, b;
  double t, p;
  int df;
};

TEST(PairedTTest, AgreesWithScipy) {
  const std::vector<TTestCase> cases{
      {{12.1, 14.3, 11.8, 15.2, 13.9, 12.7, 14.8, 13.1}, {11.4, 13.9, 12.0, 14.1, 13.2, 12.9, 13.6, 12.2},
       3.016335541394574, 0.019486909530508953, 7},
      {{3.0, 2.5, 4.1, 3.3, 2.9}, {3.3, 2.4, 4.4, 3.5, 3.0}, -2.138089935299395, 0.09930068321372677, 4},
      {{61.2, 58.9, 70.1, 64.3, 59.8, 66.0, 71.2, 62.5, 60.4, 68.8, 63.1, 65.7},
       {55.0, 57.1, 61.9, 60.2, 58.8, 59.4, 64.0, 60.1, 57.7, 62.3, 61.0, 59.9}, 6.384089563326369,
       5.1935994345353055e-05, 11},
      {{1.0, 2.0}, {0.5, 2.5}, 0.0, 1.0, 1},
  };
  for (const TTestCase& c : cases) {
    const PairedTTest r = paired_t_test(c.a, c.b);
    EXPECT_EQ(r.degrees_of_freedom, c.df);
    EXPECT_NEAR(r.t, c.t, 1e-12 * std::max(1.0, std::abs(c.t)));
    EXPECT_NEAR(r.p_two_sided, c.p, 1e-12 * std::max(1e-3, c.p)) << "df " << c.df;
  }
}

TEST(PairedTTest, DegenerateSamples) {
  const std::vector<double> a{1.0, 2.0, 3.0}, b{0.5, 1.5, 2.5};
  const PairedTTest same_shift = paired_t_test(a, b);  // every difference 0.5: no spread
  EXPECT_TRUE(std::isinf(same_shift.t) && same_shift.t > 0.0);
  EXPECT_EQ(same_shift.p_two_sided, 0.0);
  EXPECT_TRUE(std::isnan(paired_t_test(a, a).p_two_sided));
  EXPECT_THROW((void)paired_t_test(std::vector<double>{1.0}, std::vector<double>{2.0}), std::invalid_argument);
  EXPECT_THROW((void)paired_t_test(a, std::vector<double>{1.0, 2.0}), std::invalid_argument);
}

TEST(StudentT, IncompleteBetaAndCdfAgreeWithScipy) {
  EXPECT_NEAR(regularized_incomplete_beta(2.5, 0.5, 0.3), 0.01892712407194565, 1e-15);
  EXPECT_NEAR(regularized_incomplete_beta(0.5, 7.0, 0.9), 0.9999999780702158, 1e-15);
  EXPECT_NEAR(regularized_incomplete_beta(30.0, 0.5, 0.999), 0.807237306159537, 1e-14);
  EXPECT_DOUBLE_EQ(regularized_incomplete_beta(1.0, 1.0, 0.25), 0.25);
  EXPECT_NEAR(student_t_cdf(-2.1, 4), 0.05182664315880109, 1e-15);
  EXPECT_NEAR(student_t_cdf(0.7, 11), 0.7507677671528018, 1e-15);
  EXPECT_NEAR(student_t_cdf(3.5, 1), 0.9114144672170953, 1e-15);
  EXPECT_NEAR(student_t_cdf(-40.0, 9), 9.491499224669917e-12, 1e-24);
  EXPECT_EQ(student_t_cdf(0.0, 3), 0.5);
}

}  // namespace
}  // namespace ringlet::planning
