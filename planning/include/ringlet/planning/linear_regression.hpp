#pragma once
// Least-squares linear regression with an intercept (Table I's "linear regression"): speed ≈
// w · x + b. Fitted with Eigen's column-pivoting Householder QR, which also gives a usable
// (basic) solution when a feature is constant in the training set, as `diagonal` is in a fold of
// straight moves only. Unlike Weka's LinearRegression there is no attribute selection and no ridge
// term: the plain fit is the reference.
#include <array>

#include "ringlet/planning/speed_learner.hpp"

namespace ringlet::planning {

class LinearRegression final : public SpeedLearner {
 public:
  void fit(std::span<const Experience> train) override;
  [[nodiscard]] double predict(const Features& x) const noexcept override;

  /// The weights, one per feature, and the intercept last.
  [[nodiscard]] const std::array<double, kFeatureCount + 1>& coefficients() const noexcept { return coef_; }

 private:
  std::array<double, kFeatureCount + 1> coef_{};
};

}  // namespace ringlet::planning
