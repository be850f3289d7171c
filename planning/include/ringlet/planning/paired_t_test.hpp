#pragma once
// The paired t-test of the paper's Fig. 2(b): are the mission times of two systems over the same
// goals different? Two-sided, as scipy.stats.ttest_rel: t = mean(d) / (s_d / √n) with d = a − b,
// n − 1 degrees of freedom, p = P(|T| ≥ |t|). Student's t distribution is computed through the
// regularized incomplete beta function (continued fraction, modified Lentz): no Boost.
#include <span>

namespace ringlet::planning {

struct PairedTTest {
  double mean_difference = 0.0;  // mean of a − b
  double t = 0.0;                // ±inf when every difference is the same non-zero value; NaN when all are 0
  int degrees_of_freedom = 0;
  double p_two_sided = 0.0;      // NaN when t is
};

/// Needs two samples of one length n ≥ 2 (throws std::invalid_argument otherwise).
[[nodiscard]] PairedTTest paired_t_test(std::span<const double> a, std::span<const double> b);

/// I_x(a, b), the regularized incomplete beta function, for a, b > 0 and 0 ≤ x ≤ 1.
[[nodiscard]] double regularized_incomplete_beta(double a, double b, double x);

/// P(T ≤ t) for Student's t with `dof` > 0 degrees of freedom.
[[nodiscard]] double student_t_cdf(double t, double dof);

}  // namespace ringlet::planning
