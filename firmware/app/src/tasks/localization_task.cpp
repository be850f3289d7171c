#include "ringlet/firmware/tasks/localization_task.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "ringlet/localization/motion_model.hpp"

namespace ringlet::firmware {

std::unique_ptr<executive::Task> LocalizationTask::make(TaskServices& services) {
  return std::make_unique<LocalizationTask>(services.board, services.config.localization, &services.telemetry);
}

LocalizationTask::LocalizationTask(wb::Whiteboard& board, const LocalizationSettings& settings, Telemetry* telemetry)
    : board_(board), field_(settings.field), filter_(field_, settings.filter), side_(settings.side), telemetry_(telemetry) {
  if (telemetry_ != nullptr) {
    const std::size_t n = filter_.particles().size();
    snapshot_particles_.resize(n);
    telemetry_->enable_localization(kMaxSnapshots, n, localization::Observations::kMaxLines);
  }
  filter_.set_side_prior(side_);
  if (settings.start) {
    filter_.reset_to(*settings.start, settings.start_sigma_xy, settings.start_sigma_theta);
  } else {
    filter_.reset_uniform(side_);
  }
}

hal::Pose2 LocalizationTask::odometry_at(std::int64_t stamp_ns) const noexcept {
  // The newest kept pose at or before the stamp; the oldest one when the stamp is older still.
  hal::Pose2 best = odometry_.pose();
  std::int64_t best_stamp = -1;
  bool found = false;
  for (std::size_t i = 0; i < ring_count_; ++i) {
    const Stamped& s = ring_[i];
    if (s.stamp_ns <= stamp_ns && s.stamp_ns > best_stamp) {
      best = s.odometry;
      best_stamp = s.stamp_ns;
      found = true;
    }
  }
  if (!found && ring_count_ > 0) {
    const Stamped& oldest = ring_[ring_count_ < kRing ? 0 : ring_next_];
    best = oldest.odometry;
  }
  return best;
}

void LocalizationTask::run(const executive::TaskContext& ctx) noexcept {
  const std::uint64_t terms_before = filter_.terms_evaluated();
  const std::uint64_t moved_before = filter_.particles_moved();

  const wb::BodyState body = board_.get<wb::BodyState>();
  odometry_.add(body.odometry_distance, body.curvature);
  ring_[ring_next_] = {body.stamp_ns, odometry_.pose()};
  ring_next_ = (ring_next_ + 1) % kRing;
  ring_count_ = std::min(ring_count_ + 1, kRing);

  const wb::FieldLines lines = board_.get<wb::FieldLines>();
  const bool fresh = lines.sequence != last_lines_ && lines.capture_time_ns > 0;
  const localization::OdometryDelta moved = localization::delta_between(filter_odometry_, odometry_.pose());
  // Where the estimate would be now without this activation's correction (for the picture).
  const hal::Pose2 before = localization::apply(filter_.estimate().pose, moved);
  // Move the cloud when there is something to correct, or once it has gone 5 cm or 3°: the noise
  // floor per move then does not depend on the activation rate.
  if (fresh || std::fabs(moved.forward) + std::fabs(moved.left) > 0.05 || std::fabs(moved.turn) > 0.05) {
    filter_.predict(moved);
    filter_odometry_ = odometry_.pose();
  }
  if (fresh) {
    last_lines_ = lines.sequence;
    // From the robot frame at capture into the robot frame of now.
    const localization::OdometryDelta since = localization::delta_between(odometry_at(lines.capture_time_ns), odometry_.pose());
    localization::Observations obs;
    obs.capture_time_ns = lines.capture_time_ns;
    for (std::size_t i = 0; i < std::min<std::size_t>(lines.count, obs.lines.size()); ++i) {
      const hal::RobotPoint a = localization::transform_point(since, lines.ground_x0[i], lines.ground_y0[i]);
      const hal::RobotPoint b = localization::transform_point(since, lines.ground_x1[i], lines.ground_y1[i]);
      obs.add_line({a.x, a.y, b.x, b.y});
    }
    if (lines.circle_seen) {
      const hal::RobotPoint c = localization::transform_point(since, lines.circle_x, lines.circle_y);
      obs.circle_seen = true;
      obs.circle_x = c.x;
      obs.circle_y = c.y;
    }
    filter_.correct(obs);
    ++observations_;
    if (telemetry_ != nullptr) {
      const hal::Pose2& after = filter_.estimate().pose;
      const bool jumped = std::sqrt((after.x - before.x) * (after.x - before.x) + (after.y - before.y) * (after.y - before.y)) > kJumpM ||
                          std::fabs(hal::wrap_angle(after.theta - before.theta)) > kJumpRad;
      const hal::Nanos gap = ctx.frame_start - last_snapshot_;
      if (!have_snapshot_) {
        snapshot(ctx.frame_start, "start", obs);
      } else if (filter_.relocalizations() != snapshot_relocalizations_) {
        snapshot(ctx.frame_start, "relocalized", obs);
      } else if (jumped && gap >= kMinJumpGap) {
        snapshot(ctx.frame_start, "correction", obs);
      } else if (gap >= kSnapshotEvery) {
        snapshot(ctx.frame_start, "every 5 s", obs);
      }
    }
  }
  if (filter_.estimate().lost) ++lost_frames_;
  post(body.stamp_ns);

  const auto terms = static_cast<double>(filter_.terms_evaluated() - terms_before);
  const auto moved_particles = static_cast<double>(filter_.particles_moved() - moved_before);
  cost_ = kModelledBase + hal::Nanos{static_cast<std::int64_t>(terms * kModelledNsPerTerm +
                                                                moved_particles * kModelledNsPerParticleMoved)};
}

void LocalizationTask::snapshot(hal::Nanos when, std::string_view reason, const localization::Observations& obs) noexcept {
  have_snapshot_ = true;
  last_snapshot_ = when;
  snapshot_relocalizations_ = filter_.relocalizations();
  const std::span<const localization::Particle> cloud = filter_.particles();
  for (std::size_t i = 0; i < cloud.size(); ++i) snapshot_particles_[i] = {cloud[i].x, cloud[i].y, cloud[i].theta};
  // The segments (robot frame of now) into the world with the corrected estimate.
  const hal::Pose2& e = filter_.estimate().pose;
  const hal::RobotToWorld to_world(e);
  for (std::size_t i = 0; i < obs.line_count; ++i) {
    const localization::LineObservation& l = obs.lines[i];
    snapshot_segments_[i] = {to_world.point(l.x0, l.y0), to_world.point(l.x1, l.y1)};
  }
  telemetry_->record_snapshot(std::chrono::duration<double>(when).count(), e, reason,
                              std::span<const hal::Pose2>(snapshot_particles_.data(), cloud.size()),
                              std::span<const hal::WorldSegment>(snapshot_segments_.data(), obs.line_count));
}

void LocalizationTask::post(std::int64_t stamp_ns) noexcept {
  const localization::Estimate& e = filter_.estimate();
  // The filter's pose is that of the last move; odometry since then brings it to now.
  const hal::Pose2 now = localization::apply(e.pose, localization::delta_between(filter_odometry_, odometry_.pose()));
  board_.post(wb::Pose{now.x, now.y, now.theta, e.reliable()});
  wb::Localization m{};
  m.stamp_ns = stamp_ns;
  m.x = now.x;
  m.y = now.y;
  m.theta = now.theta;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m.covariance[static_cast<std::size_t>(3 * r + c)] = e.covariance(r, c);
  }
  m.share = e.share;
  m.mirror_x = e.mirror.x;
  m.mirror_y = e.mirror.y;
  m.mirror_theta = e.mirror.theta;
  m.mirror_share = e.mirror_share;
  m.quality = e.quality;
  m.confidence = e.confidence;
  m.lost = e.lost;
  m.ambiguous = e.ambiguous;
  m.relocalizations = static_cast<std::uint32_t>(filter_.relocalizations());
  m.lost_frames = lost_frames_;
  m.observations = observations_;
  board_.post(m);
}

}  // namespace ringlet::firmware
