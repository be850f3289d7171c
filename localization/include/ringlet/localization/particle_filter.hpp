#pragma once
// Monte Carlo localization on the known field: a fixed number of particles (sized at start-up,
// nothing allocated afterwards), odometry with noise, the observation model, low-variance
// resampling and sensor resetting driven by the augmented-MCL averages (Thrun, Burgard and Fox,
// ch. 8.3.5): when the short-term fit falls below the long-term one, part of the particles are
// replaced by poses that explain the current observation alone (pose_candidates.hpp). The
// estimate is the heaviest cluster, with its covariance, its point mirror's weight, a fit quality
// and the lost / ambiguous flags (estimate.hpp). All randomness comes from one SplitMix64 seeded
// at construction: the same inputs give the same bits on every target.
#include <cstddef>
#include <cstdint>
#include <array>
#include <span>
#include <string>
#include <vector>

#include "ringlet/hal/geometry.hpp"
#include "ringlet/hal/splitmix64.hpp"
#include "ringlet/localization/estimate.hpp"
#include "ringlet/localization/field_model.hpp"
#include "ringlet/localization/motion_model.hpp"
#include "ringlet/localization/observation_model.hpp"

namespace ringlet::localization {

struct Particle {
  double x = 0.0, y = 0.0, theta = 0.0;
  double weight = 0.0;
};

struct FilterParams {
  int particles = 300;
  MotionNoise motion{};
  ObservationParams observation{};
  std::uint64_t seed = 0x4C4F43414C495A45ULL;  // "LOCALIZE"
  double alpha_slow = 0.05;          // long-term average of the fit, per correction
  double alpha_fast = 0.5;           // short-term average
  double reset_drop = 0.7;           // inject only when w_fast / w_slow falls below this
  double max_reset_share = 0.3;      // at most this share of the particles injected per correction
  double lost_reset_share = 0.1;     // injected per correction at least, while lost
  double quality_alpha = 0.3;        // the estimate's fit quality, smoothed over corrections
  double lost_quality = 0.45;        // below: the estimate no longer explains what the robot sees
  double lost_spread_m = 0.6;        // position σ above which the estimate counts as lost
  double cluster_radius_m = 0.6;     // particles this close (and cluster_angle_deg) form a hypothesis
  double cluster_angle_deg = 40.0;
  double switch_ratio = 0.6;         // the main hypothesis moves only to a cluster 1/0.6 times heavier
  double ambiguous_share = 0.15;     // a mirror hypothesis with this share makes the estimate ambiguous
  double continuity_m = 1.0;         // a recovered pose this close to the dead-reckoned last good
  double continuity_deg = 45.0;      //   one keeps the side it had (no mirror ambiguity)
};

/// Empty when the parameters are usable, else what is wrong (naming the [localization] key).
[[nodiscard]] std::string check(const FilterParams& p);

class ParticleFilter {
 public:
  static constexpr std::size_t kMaxCandidates = 64;

  /// Sizes everything (allocates); `field` must outlive the filter.
  ParticleFilter(const FieldModel& field, const FilterParams& params);

  /// Known pose (a kick-off position): the cloud around it, the side resolved.
  void reset_to(const hal::Pose2& pose, double sigma_xy, double sigma_theta) noexcept;
  /// Unknown pose: uniform on the carpet (x_sign > 0 or < 0: that half only, a prior that also
  /// resolves the mirror), the estimate lost until observations say otherwise.
  void reset_uniform(double x_sign = 0.0) noexcept;

  /// Moves every particle by the odometry delta, with noise.
  void predict(const OdometryDelta& delta) noexcept;
  /// Weighs by the observations (robot frame of now), resamples, injects, re-estimates.
  void correct(const Observations& obs) noexcept;
  /// When the estimate is ambiguous, keeps the hypothesis whose x has the sign of `x_sign` (the
  /// prior a team has: its own half at a kick-off or on returning from a penalty).
  void resolve_mirror(double x_sign) noexcept;
  /// The side prior applied whenever the filter recovers somewhere continuity cannot vouch for
  /// (x_sign > 0 or < 0: that half; 0: none, and such a recovery is reported ambiguous).
  void set_side_prior(double x_sign) noexcept { side_prior_ = x_sign; }

  [[nodiscard]] const Estimate& estimate() const noexcept { return estimate_; }
  [[nodiscard]] std::span<const Particle> particles() const noexcept { return particles_; }
  [[nodiscard]] const FilterParams& params() const noexcept { return params_; }
  [[nodiscard]] const ObservationModel& model() const noexcept { return model_; }
  /// The last correction's prepared observations (for drawing what drove it).
  [[nodiscard]] const PreparedObservations& last_observations() const noexcept { return prepared_; }
  /// Work done since construction, for the cost model: observation terms evaluated and particles moved.
  [[nodiscard]] std::uint64_t terms_evaluated() const noexcept { return terms_evaluated_; }
  [[nodiscard]] std::uint64_t particles_moved() const noexcept { return particles_moved_; }
  [[nodiscard]] double fit_slow() const noexcept { return w_slow_; }
  [[nodiscard]] double fit_fast() const noexcept { return w_fast_; }
  /// Kidnaps noticed: times the estimate settled away from the dead-reckoned last good pose, by a
  /// jump while tracking or by recovering elsewhere after being lost (not the first fix of an
  /// unknown start: there is no last good pose then).
  [[nodiscard]] std::uint64_t relocalizations() const noexcept { return relocalizations_; }
  /// Particles the last correction replaced with candidates.
  [[nodiscard]] std::size_t last_injected() const noexcept { return last_injected_; }

 private:
  void normalise() noexcept;
  void resample(std::size_t inject) noexcept;
  void update_estimate() noexcept;   // clusters, then the lost / ambiguous flags and confidence
  void compute_clusters() noexcept;  // main hypothesis, its covariance, the mirror's share
  void flip_towards(const hal::Pose2& keep) noexcept;

  const FieldModel& field_;
  FilterParams params_;
  ObservationModel model_;
  hal::SplitMix64 rng_;
  std::vector<Particle> particles_;
  std::vector<Particle> scratch_;
  std::vector<double> bins_;  // cluster search: weight per (x, y, heading) cell
  std::size_t bins_x_ = 0, bins_y_ = 0;
  PreparedObservations prepared_{};
  std::array<hal::Pose2, kMaxCandidates> candidates_{};
  Estimate estimate_{};
  double w_slow_ = 0.0, w_fast_ = 0.0;
  double quality_ = 0.0;
  bool side_resolved_ = false;     // the mirror hypothesis was excluded by a prior or by continuity
  double side_prior_ = 0.0;
  bool was_lost_ = true;
  hal::Pose2 last_good_{};         // the last confident estimate, moved on by odometry since
  bool have_last_good_ = false;
  bool have_estimate_ = false;     // estimate_.pose is a hypothesis to keep (hysteresis)
  std::size_t last_injected_ = 0;
  std::uint64_t relocalizations_ = 0;
  std::uint64_t terms_evaluated_ = 0;
  std::uint64_t particles_moved_ = 0;
};

}  // namespace ringlet::localization
