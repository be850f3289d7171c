#pragma once
// A robot driving the SPL field's mission loop on synthetic views, for the filter's scenario
// tests: a waypoint follower moves the true pose at 30 Hz, the odometry it reports has a scale
// bias, a curvature bias and noise, the head sweeps ±60°, and each step's view (with dropped and
// false lines, as vision has) goes to the filter in the robot frame of that step.
#include <array>
#include <cmath>
#include <functional>
#include <numbers>

#include "ringlet/localization/gaussian.hpp"
#include "ringlet/localization/particle_filter.hpp"
#include "ringlet/localization/pose_candidates.hpp"
#include "ringlet/localization/synthetic_view.hpp"

namespace ringlet::localization::test {

struct StepRecord {
  double t = 0.0;
  hal::Pose2 truth{};
  Estimate estimate{};
  [[nodiscard]] double error() const { return std::hypot(estimate.pose.x - truth.x, estimate.pose.y - truth.y); }
  [[nodiscard]] double mirror_error() const {
    return std::hypot(estimate.mirror.x - truth.x, estimate.mirror.y - truth.y);
  }
  /// Confident, unambiguous and more than `m` away: silently wrong.
  [[nodiscard]] bool silently_wrong(double m = 0.5) const { return estimate.reliable() && error() > m; }
};

class Scenario {
 public:
  static constexpr double kDt = 1.0 / 30.0;
  static constexpr double kSpeed = 0.6;

  explicit Scenario(ParticleFilter& filter, hal::Pose2 start, std::uint64_t seed = 5) : filter_(filter), truth_(start), rng_(seed) {}

  bool observe = true;
  double odometry_scale_bias = 0.03;  // reports 3 % more than driven
  double odometry_curvature_bias = 0.02;
  ViewParams view{.drop = 0.15, .false_line = 0.2};

  void teleport(const hal::Pose2& p) { truth_ = p; }
  [[nodiscard]] const hal::Pose2& truth() const { return truth_; }

  /// Drives for `seconds`, calling `each` after every step.
  void run(double seconds, const std::function<void(const StepRecord&)>& each = {}) {
    const int steps = static_cast<int>(seconds / kDt + 0.5);
    for (int i = 0; i < steps; ++i) {
      step();
      if (each) each({t_, truth_, filter_.estimate()});
    }
  }

 private:
  void step() {
    static constexpr std::array<std::array<double, 2>, 5> kGoals{{{3.0, -2.2}, {3.0, 2.2}, {0.0, 2.2}, {-3.0, 2.2}, {-3.0, -1.2}}};
    const auto& g = kGoals[goal_ % kGoals.size()];
    if (std::hypot(g[0] - truth_.x, g[1] - truth_.y) < 0.3) ++goal_;
    const double error = hal::wrap_angle(hal::bearing_to(truth_, g[0], g[1]) - truth_.theta);
    const double curvature = std::clamp(2.0 * error, -2.0, 2.0);
    const double ds = kSpeed * kDt;
    const double turn = ds * curvature;
    truth_ = {truth_.x + ds * std::sin(truth_.theta + 0.5 * turn), truth_.y + ds * std::cos(truth_.theta + 0.5 * turn),
              hal::wrap_angle(truth_.theta + turn)};
    // The odometry the filter gets: biased and noisy.
    const double mds = ds * (1.0 + odometry_scale_bias + 0.05 * standard_normal(rng_));
    const double mk = curvature + odometry_curvature_bias + 0.05 * standard_normal(rng_);
    OdometryIntegrator odo;
    odo.add(0.0, mk);
    odo.add(mds, mk);
    filter_.predict(delta_between({}, odo.pose()));
    t_ += kDt;
    if (observe) {
      view.head_yaw = 1.0 * std::sin(0.8 * t_);
      filter_.correct(synthetic_view(filter_.model().field(), truth_, view, rng_));
    }
  }

  ParticleFilter& filter_;
  hal::Pose2 truth_;
  hal::SplitMix64 rng_;
  std::size_t goal_ = 0;
  double t_ = 0.0;
};

}  // namespace ringlet::localization::test
