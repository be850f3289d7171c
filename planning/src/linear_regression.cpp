#include "ringlet/planning/linear_regression.hpp"

#include <Eigen/QR>

namespace ringlet::planning {

void LinearRegression::fit(std::span<const Experience> train) {
  coef_.fill(0.0);
  if (train.empty()) return;
  const auto n = static_cast<Eigen::Index>(train.size());
  Eigen::MatrixXd a(n, kFeatureCount + 1);
  Eigen::VectorXd y(n);
  for (Eigen::Index r = 0; r < n; ++r) {
    const Experience& e = train[static_cast<std::size_t>(r)];
    for (int c = 0; c < kFeatureCount; ++c) a(r, c) = e.features[static_cast<std::size_t>(c)];
    a(r, kFeatureCount) = 1.0;
    y(r) = e.achieved_speed;
  }
  const Eigen::VectorXd w = a.colPivHouseholderQr().solve(y);
  for (int c = 0; c <= kFeatureCount; ++c) coef_[static_cast<std::size_t>(c)] = w(c);
}

double LinearRegression::predict(const Features& x) const noexcept {
  double sum = coef_[kFeatureCount];
  for (std::size_t i = 0; i < x.size(); ++i) sum += coef_[i] * x[i];
  return sum;
}

}  // namespace ringlet::planning
