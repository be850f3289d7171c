#include "ringlet/localization/particle_filter.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ringlet/localization/gaussian.hpp"
#include "ringlet/localization/pose_candidates.hpp"

namespace ringlet::localization {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kBinSize = 0.5;            // m: the cluster search's cells
constexpr std::size_t kHeadingBins = 8;     // 45° each

bool close_to(const Particle& p, const hal::Pose2& c, double r2, double angle) noexcept {
  const double dx = p.x - c.x;
  const double dy = p.y - c.y;
  return dx * dx + dy * dy <= r2 && std::fabs(hal::wrap_angle(p.theta - c.theta)) <= angle;
}

}  // namespace

std::string check(const FilterParams& p) {
  if (p.particles < 10 || p.particles > 5000) return "particles must be between 10 and 5000";
  const auto in01 = [](double v) { return std::isfinite(v) && v > 0.0 && v <= 1.0; };
  if (!in01(p.alpha_slow) || !in01(p.alpha_fast) || p.alpha_slow >= p.alpha_fast)
    return "alpha_slow and alpha_fast must be in (0, 1] with alpha_slow < alpha_fast";
  if (!std::isfinite(p.max_reset_share) || p.max_reset_share < 0.0 || p.max_reset_share > 0.9)
    return "max_reset_share must be between 0 and 0.9";
  if (!std::isfinite(p.lost_reset_share) || p.lost_reset_share < 0.0 || p.lost_reset_share > p.max_reset_share)
    return "lost_reset_share must be between 0 and max_reset_share";
  if (!(p.observation.line_sigma > 0.0) || !(p.observation.circle_sigma > 0.0))
    return "line_sigma and circle_sigma must be positive";
  return {};
}

ParticleFilter::ParticleFilter(const FieldModel& field, const FilterParams& params)
    : field_(field), params_(params), model_(field, params.observation), rng_(params.seed) {
  const auto n = static_cast<std::size_t>(std::max(params.particles, 10));
  particles_.resize(n);
  scratch_.resize(n);
  const FieldDimensions& d = field.dimensions();
  bins_x_ = static_cast<std::size_t>(std::ceil((d.length + 2.0 * d.border) / kBinSize)) + 1;
  bins_y_ = static_cast<std::size_t>(std::ceil((d.width + 2.0 * d.border) / kBinSize)) + 1;
  bins_.resize(bins_x_ * bins_y_ * kHeadingBins);
  reset_uniform();
}

void ParticleFilter::reset_to(const hal::Pose2& pose, double sigma_xy, double sigma_theta) noexcept {
  const double w = 1.0 / static_cast<double>(particles_.size());
  for (Particle& p : particles_) {
    p.x = pose.x + sigma_xy * standard_normal(rng_);
    p.y = pose.y + sigma_xy * standard_normal(rng_);
    p.theta = hal::wrap_angle(pose.theta + sigma_theta * standard_normal(rng_));
    p.weight = w;
  }
  side_resolved_ = true;
  was_lost_ = false;
  have_estimate_ = false;
  last_good_ = pose;
  have_last_good_ = true;
  quality_ = 0.5 * (1.0 + params_.lost_quality);  // a known pose is trusted until observations disagree
  w_slow_ = w_fast_ = 0.0;
  update_estimate();
}

void ParticleFilter::reset_uniform(double x_sign) noexcept {
  const double w = 1.0 / static_cast<double>(particles_.size());
  for (Particle& p : particles_) {
    const hal::Pose2 q = uniform_pose(field_, rng_, x_sign);
    p = {q.x, q.y, q.theta, w};
  }
  side_resolved_ = x_sign != 0.0;
  if (x_sign != 0.0) side_prior_ = x_sign;
  was_lost_ = true;
  have_estimate_ = false;
  have_last_good_ = false;
  quality_ = 0.0;
  w_slow_ = w_fast_ = 0.0;
  update_estimate();
}

void ParticleFilter::predict(const OdometryDelta& delta) noexcept {
  for (Particle& p : particles_) {
    const hal::Pose2 moved = apply(hal::Pose2{p.x, p.y, p.theta}, noisy(delta, params_.motion, rng_));
    p.x = moved.x;
    p.y = moved.y;
    p.theta = moved.theta;
  }
  particles_moved_ += particles_.size();
  if (have_last_good_) last_good_ = apply(last_good_, delta);
  update_estimate();
}

void ParticleFilter::normalise() noexcept {
  double total = 0.0;
  for (const Particle& p : particles_) total += p.weight;
  const double uniform_w = 1.0 / static_cast<double>(particles_.size());
  if (!(total > 0.0) || !std::isfinite(total)) {
    for (Particle& p : particles_) p.weight = uniform_w;  // nothing fits at all: start over evenly
    return;
  }
  const double inv = 1.0 / total;
  for (Particle& p : particles_) p.weight *= inv;
}

void ParticleFilter::correct(const Observations& obs) noexcept {
  prepared_.prepare(obs, params_.observation);
  last_injected_ = 0;
  if (prepared_.empty()) return;
  // Weigh. The filter's fit (for the augmented-MCL averages) is the prior-weighted mean quality.
  double fit = 0.0;
  for (Particle& p : particles_) {
    const Fit f = model_.evaluate(prepared_, hal::Pose2{p.x, p.y, p.theta});
    fit += p.weight * f.quality;
    p.weight *= f.likelihood;
  }
  terms_evaluated_ += particles_.size() * prepared_.work(params_.observation);
  normalise();
  if (w_slow_ == 0.0) {
    w_slow_ = w_fast_ = fit;
  } else {
    w_slow_ += params_.alpha_slow * (fit - w_slow_);
    w_fast_ += params_.alpha_fast * (fit - w_fast_);
  }
  compute_clusters();
  // The estimate's own fit, smoothed: it says whether the estimate explains what is seen.
  const Fit at = model_.evaluate(prepared_, estimate_.pose);
  terms_evaluated_ += prepared_.work(params_.observation);
  quality_ += params_.quality_alpha * (at.quality - quality_);
  update_estimate();

  // Augmented MCL injects 1 − w_fast / w_slow; below a clear drop (reset_drop) the short-term
  // average only wobbles with what the camera happens to see, and a candidate that explains one
  // line as well as the truth does would dilute a good cloud for nothing.
  const double ratio = w_slow_ > 0.0 ? w_fast_ / w_slow_ : 1.0;
  double share = ratio < params_.reset_drop ? 1.0 - ratio : 0.0;
  if (estimate_.lost) share = std::max(share, params_.lost_reset_share);
  share = std::clamp(share, 0.0, params_.max_reset_share);
  const auto inject = std::min(static_cast<std::size_t>(share * static_cast<double>(particles_.size()) + 0.5),
                               kMaxCandidates);
  resample(inject & ~std::size_t{1});  // mirror pairs
}

void ParticleFilter::resample(std::size_t inject) noexcept {
  const std::size_t n = particles_.size();
  const std::size_t keep = n - inject;
  // Low-variance resampling: one draw, `keep` evenly spaced pointers into the cumulative weights.
  const double step = 1.0 / static_cast<double>(keep);
  double target = uniform(rng_) * step;
  double cumulative = particles_[0].weight;
  std::size_t i = 0;
  for (std::size_t k = 0; k < keep; ++k) {
    while (target > cumulative && i + 1 < n) cumulative += particles_[++i].weight;
    scratch_[k] = particles_[i];
    target += step;
  }
  std::size_t made = inject == 0 ? 0 : pose_candidates(prepared_, field_, rng_, std::span(candidates_.data(), inject));
  for (std::size_t k = 0; k < made; ++k) scratch_[keep + k] = {candidates_[k].x, candidates_[k].y, candidates_[k].theta, 0.0};
  // Fewer candidates than asked (segments that land off the carpet): fill with resampled ones.
  for (std::size_t k = keep + made; k < n; ++k) scratch_[k] = scratch_[k % std::max<std::size_t>(keep, 1)];
  last_injected_ = made;
  const double w = 1.0 / static_cast<double>(n);
  for (std::size_t k = 0; k < n; ++k) {
    particles_[k] = scratch_[k];
    particles_[k].weight = w;
  }
}

void ParticleFilter::resolve_mirror(double x_sign) noexcept {
  if (x_sign == 0.0 || !estimate_.ambiguous) return;
  flip_towards(estimate_.pose.x * x_sign >= 0.0 ? estimate_.pose : estimate_.mirror);
  update_estimate();
}

void ParticleFilter::update_estimate() noexcept {
  compute_clusters();
  Estimate& e = estimate_;
  e.lost = quality_ < params_.lost_quality || e.sigma_xy() > params_.lost_spread_m || e.share + e.mirror_share < 0.5;
  const double c2 = params_.continuity_m * params_.continuity_m;
  const double angle = params_.continuity_deg * kPi / 180.0;
  const auto near = [&](const hal::Pose2& p) {
    const double dx = p.x - last_good_.x;
    const double dy = p.y - last_good_.y;
    return have_last_good_ && dx * dx + dy * dy <= c2 && std::fabs(hal::wrap_angle(p.theta - last_good_.theta)) <= angle;
  };
  if (!e.lost && !was_lost_ && have_last_good_ && !near(e.pose)) {
    // The main hypothesis jumped away from where odometry says the robot went: the old one was
    // wrong (a kidnap the fit had not yet noticed). Reported as lost for this update; the next
    // one goes through the recovery below.
    e.lost = true;
    ++relocalizations_;
    have_last_good_ = false;
  }
  if (!e.lost && was_lost_) {
    // Recovered. Near the dead-reckoned last good pose (or its mirror): continuity says which
    // side. Anywhere else (a kidnap, an unknown start) the mirror explains the lines as well:
    // the side prior decides if there is one, else the estimate stays ambiguous. Recovering away
    // from a last good pose is a relocalization too: a kidnap the fit noticed first (lost), then
    // the new place.
    if (have_last_good_ && !near(e.pose) && !near(e.mirror)) ++relocalizations_;
    if (near(e.pose)) {
      flip_towards(e.pose);
    } else if (near(e.mirror)) {
      flip_towards(e.mirror);
    } else if (side_prior_ != 0.0) {
      flip_towards(e.pose.x * side_prior_ >= 0.0 ? e.pose : e.mirror);
    } else {
      side_resolved_ = false;
    }
  }
  was_lost_ = e.lost;
  e.ambiguous = !side_resolved_ || e.mirror_share >= params_.ambiguous_share;
  if (!e.lost && !e.ambiguous) {
    last_good_ = e.pose;
    have_last_good_ = true;
  }
  const double fit = std::clamp((quality_ - params_.lost_quality) / (1.0 - params_.lost_quality), 0.0, 1.0);
  const double tight = 1.0 / (1.0 + e.sigma_xy() * e.sigma_xy() / (0.25 * 0.25));
  e.confidence = e.share * fit * tight * (e.ambiguous ? 0.5 : 1.0);
}

void ParticleFilter::flip_towards(const hal::Pose2& keep) noexcept {
  // Both hypotheses explain the lines equally: the one to drop becomes its mirror.
  const hal::Pose2 drop = mirrored(keep);
  const double r2 = params_.cluster_radius_m * params_.cluster_radius_m;
  const double angle = params_.cluster_angle_deg * kPi / 180.0;
  for (Particle& p : particles_) {
    if (close_to(p, drop, r2, angle)) {
      p.x = -p.x;
      p.y = -p.y;
      p.theta = hal::wrap_angle(p.theta + kPi);
    }
  }
  side_resolved_ = true;
  compute_clusters();
}

void ParticleFilter::compute_clusters() noexcept {
  // 1. The heaviest cell of a coarse (x, y, heading) grid seeds the main hypothesis.
  std::fill(bins_.begin(), bins_.end(), 0.0);
  const FieldDimensions& d = field_.dimensions();
  const double x0 = -0.5 * d.length - d.border;
  const double y0 = -0.5 * d.width - d.border;
  const auto cell = [&](const Particle& p) {
    const auto bx = static_cast<std::size_t>(std::clamp((p.x - x0) / kBinSize, 0.0, static_cast<double>(bins_x_ - 1)));
    const auto by = static_cast<std::size_t>(std::clamp((p.y - y0) / kBinSize, 0.0, static_cast<double>(bins_y_ - 1)));
    const auto bt = static_cast<std::size_t>((p.theta + kPi) / (2.0 * kPi) * kHeadingBins) % kHeadingBins;
    return (by * bins_x_ + bx) * kHeadingBins + bt;
  };
  std::size_t best = 0;
  for (const Particle& p : particles_) {
    const std::size_t c = cell(p);
    bins_[c] += p.weight;
    if (bins_[c] > bins_[best]) best = c;
  }
  hal::Pose2 seed{};
  double seed_w = -1.0;
  for (const Particle& p : particles_) {  // the heaviest particle of that cell
    if (cell(p) == best && p.weight > seed_w) {
      seed = {p.x, p.y, p.theta};
      seed_w = p.weight;
    }
  }
  const double r2 = params_.cluster_radius_m * params_.cluster_radius_m;
  const double angle = params_.cluster_angle_deg * kPi / 180.0;
  // Hysteresis: the previous hypothesis stays unless the new one is clearly heavier, so that the
  // estimate does not jump between two poses that explain one line equally.
  if (have_estimate_) {
    double near_previous = 0.0, near_seed = 0.0;
    for (const Particle& p : particles_) {
      if (close_to(p, estimate_.pose, r2, angle)) near_previous += p.weight;
      if (close_to(p, seed, r2, angle)) near_seed += p.weight;
    }
    if (near_previous >= params_.switch_ratio * near_seed && near_previous > 0.0) seed = estimate_.pose;
  }
  have_estimate_ = true;
  // 2. Twice: the weighted mean of the particles near the seed (headings relative to the seed,
  //    so the circular mean needs no trigonometry); then the covariance around it.
  double share = 0.0;
  for (int pass = 0; pass < 2; ++pass) {
    double sw = 0.0, sx = 0.0, sy = 0.0, st = 0.0;
    for (const Particle& p : particles_) {
      if (!close_to(p, seed, r2, angle)) continue;
      sw += p.weight;
      sx += p.weight * p.x;
      sy += p.weight * p.y;
      st += p.weight * hal::wrap_angle(p.theta - seed.theta);
    }
    if (sw <= 0.0) break;
    seed = {sx / sw, sy / sw, hal::wrap_angle(seed.theta + st / sw)};
    share = sw;
  }
  double cxx = 0.0, cxy = 0.0, cxt = 0.0, cyy = 0.0, cyt = 0.0, ctt = 0.0, mirror_share = 0.0;
  const hal::Pose2 mirror = mirrored(seed);
  for (const Particle& p : particles_) {
    if (close_to(p, mirror, r2, angle)) mirror_share += p.weight;
    if (!close_to(p, seed, r2, angle)) continue;
    const double dx = p.x - seed.x;
    const double dy = p.y - seed.y;
    const double dt = hal::wrap_angle(p.theta - seed.theta);
    cxx += p.weight * dx * dx;
    cxy += p.weight * dx * dy;
    cxt += p.weight * dx * dt;
    cyy += p.weight * dy * dy;
    cyt += p.weight * dy * dt;
    ctt += p.weight * dt * dt;
  }
  Estimate& e = estimate_;
  e.pose = seed;
  e.mirror = mirror;
  e.share = share;
  e.mirror_share = mirror_share;
  const double inv = share > 0.0 ? 1.0 / share : 0.0;
  e.covariance << cxx * inv, cxy * inv, cxt * inv, cxy * inv, cyy * inv, cyt * inv, cxt * inv, cyt * inv, ctt * inv;
  e.quality = quality_;
  e.initialised = true;
}

}  // namespace ringlet::localization
