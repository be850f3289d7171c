#include "ringlet/localization/estimate.hpp"

#include <cmath>

namespace ringlet::localization {

double Estimate::sigma_xy() const noexcept {
  // The larger eigenvalue of the position block, in closed form (plain arithmetic: the same bits
  // on every target, since the lost flag depends on it).
  const double a = covariance(0, 0);
  const double b = covariance(0, 1);
  const double c = covariance(1, 1);
  const double h = 0.5 * (a - c);
  return std::sqrt(0.5 * (a + c) + std::sqrt(h * h + b * b));
}

double Estimate::sigma_theta() const noexcept { return std::sqrt(covariance(2, 2)); }

}  // namespace ringlet::localization
