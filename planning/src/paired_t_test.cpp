#include "ringlet/planning/paired_t_test.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace ringlet::planning {
namespace {

/// The continued fraction of I_x(a, b) (converges fast for x < (a + 1) / (a + b + 2)), evaluated
/// with the modified Lentz method: f = 1 + n₁/(1 + n₂/(1 + …)), returned as f − 1, where
///   n₁ = 1, n₂ₘ = m(b − m)x / ((a + 2m − 1)(a + 2m)), n₂ₘ₊₁ = −(a + m)(a + b + m)x / ((a + 2m)(a + 2m + 1)).
double beta_continued_fraction(double a, double b, double x) {
  constexpr double kTiny = 1e-300;
  constexpr double kTolerance = 1e-16;
  constexpr int kMaxTerms = 1000;
  double f = 1.0, c = 1.0, d = 0.0;
  for (int i = 0; i <= kMaxTerms; ++i) {
    const double m = static_cast<double>(i / 2);
    double numerator = 1.0;
    if (i > 0 && i % 2 == 0) {
      numerator = m * (b - m) * x / ((a + 2.0 * m - 1.0) * (a + 2.0 * m));
    } else if (i % 2 == 1) {
      numerator = -(a + m) * (a + b + m) * x / ((a + 2.0 * m) * (a + 2.0 * m + 1.0));
    }
    d = 1.0 + numerator * d;
    d = 1.0 / (std::abs(d) < kTiny ? kTiny : d);
    c = 1.0 + numerator / c;
    if (std::abs(c) < kTiny) c = kTiny;
    const double step = c * d;
    f *= step;
    if (std::abs(1.0 - step) < kTolerance) return f - 1.0;
  }
  return f - 1.0;  // not converged in kMaxTerms: only for extreme a, b, far beyond a t-test's
}

}  // namespace

double regularized_incomplete_beta(double a, double b, double x) {
  if (!(a > 0.0) || !(b > 0.0) || !(x >= 0.0 && x <= 1.0))
    throw std::invalid_argument("regularized_incomplete_beta needs a, b > 0 and 0 <= x <= 1");
  if (x == 0.0 || x == 1.0) return x;
  // x^a (1 − x)^b / (a B(a, b)), in logarithms.
  const double log_front =
      std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
  if (x < (a + 1.0) / (a + b + 2.0)) return std::exp(log_front) / a * beta_continued_fraction(a, b, x);
  // The symmetry I_x(a, b) = 1 − I_{1−x}(b, a) keeps the fraction in its fast region.
  return 1.0 - std::exp(log_front) / b * beta_continued_fraction(b, a, 1.0 - x);
}

double student_t_cdf(double t, double dof) {
  if (!(dof > 0.0)) throw std::invalid_argument("student_t_cdf needs dof > 0");
  if (std::isnan(t)) return t;
  if (std::isinf(t)) return t > 0.0 ? 1.0 : 0.0;
  // P(|T| ≥ |t|) = I_{ν/(ν + t²)}(ν/2, 1/2).
  const double tail = 0.5 * regularized_incomplete_beta(dof / 2.0, 0.5, dof / (dof + t * t));
  return t > 0.0 ? 1.0 - tail : tail;
}

PairedTTest paired_t_test(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size() || a.size() < 2)
    throw std::invalid_argument("paired_t_test needs two samples of one length, at least 2; got " +
                                std::to_string(a.size()) + " and " + std::to_string(b.size()));
  const auto n = static_cast<double>(a.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += a[i] - b[i];
  const double mean = sum / n;
  double ss = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double dev = (a[i] - b[i]) - mean;
    ss += dev * dev;
  }
  PairedTTest r;
  r.mean_difference = mean;
  r.degrees_of_freedom = static_cast<int>(a.size()) - 1;
  const double se = std::sqrt(ss / (n - 1.0) / n);
  if (se == 0.0) {
    r.t = mean == 0.0 ? std::numeric_limits<double>::quiet_NaN() : std::copysign(std::numeric_limits<double>::infinity(), mean);
    r.p_two_sided = mean == 0.0 ? std::numeric_limits<double>::quiet_NaN() : 0.0;
    return r;
  }
  r.t = mean / se;
  const double dof = static_cast<double>(r.degrees_of_freedom);
  r.p_two_sided = regularized_incomplete_beta(dof / 2.0, 0.5, dof / (dof + r.t * r.t));
  return r;
}

}  // namespace ringlet::planning
