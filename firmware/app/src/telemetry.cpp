#include "ringlet/firmware/telemetry.hpp"

#include <algorithm>
#include <cmath>

#include "ringlet/firmware/config.hpp"

namespace ringlet::firmware {

Telemetry::Telemetry(std::size_t trajectory_capacity, std::size_t collision_capacity) {
  // The configuration refuses runs that need more; the cap here keeps a stack built from any
  // other config (a test, a tool) from reserving without limit.
  trajectory_capacity_ = std::min<std::size_t>(trajectory_capacity, kMaxTrajectorySamples);
  trajectory_.reserve(trajectory_capacity_);
  collision_points_.reserve(collision_capacity);
}

// push_back below never reallocates: each is guarded by the capacity reserved at start-up.
void Telemetry::record_pose(const hal::Pose2& pose) noexcept {
  if (trajectory_.size() < trajectory_.capacity()) {
    trajectory_.push_back(pose);
  } else {
    ++dropped_;
  }
}

void Telemetry::record_collision(const hal::Pose2& pose) noexcept {
  ++collisions_;
  if (collision_points_.size() < collision_points_.capacity()) collision_points_.push_back({pose.x, pose.y});
}

void Telemetry::record_odometry(double distance) noexcept {
  if (have_odometry_) odometry_path_ += std::abs(distance - last_odometry_);
  have_odometry_ = true;
  last_odometry_ = distance;
}

void Telemetry::record_progress(std::size_t goals_reached, std::size_t goal_count, std::uint64_t frame) noexcept {
  while (goals_stamped_ < goals_reached && goals_stamped_ < goal_frames_.size()) goal_frames_[goals_stamped_++] = frame;
  goals_reached_ = goals_reached;
  goal_count_ = goal_count;
}

LocalizationTrack& Telemetry::enable_localization(std::size_t snapshots, std::size_t particles, std::size_t segments) {
  localization_enabled_ = true;
  localization_.truth.reserve(trajectory_capacity_);
  localization_.snapshots.reserve(snapshots);
  localization_.particles.reserve(snapshots * particles);
  localization_.segments.reserve(snapshots * segments);
  return localization_;
}

void Telemetry::record_true_pose(const hal::Pose2& pose) noexcept {
  if (localization_.truth.size() < localization_.truth.capacity()) {
    localization_.truth.push_back(pose);
  } else {
    ++localization_.dropped_truth;
  }
}

bool Telemetry::snapshot_fits(std::size_t particles, std::size_t segments) const noexcept {
  const LocalizationTrack& l = localization_;
  return l.snapshots.size() < l.snapshots.capacity() && l.particles.size() + particles <= l.particles.capacity() &&
         l.segments.size() + segments <= l.segments.capacity();
}

void Telemetry::record_snapshot(double time_s, const hal::Pose2& estimate, std::string_view reason,
                                std::span<const hal::Pose2> particles,
                                std::span<const hal::WorldSegment> segments) noexcept {
  if (!snapshot_fits(particles.size(), segments.size())) {
    ++localization_.dropped_snapshots;
    return;
  }
  LocalizationTrack& l = localization_;
  l.particles.insert(l.particles.end(), particles.begin(), particles.end());
  l.segments.insert(l.segments.end(), segments.begin(), segments.end());
  l.snapshots.push_back({time_s, estimate, static_cast<std::uint32_t>(l.particles.size()),
                         static_cast<std::uint32_t>(l.segments.size()), reason});
}

hal::LocalizationPicture Telemetry::localization_picture() const noexcept {
  if (!localization_enabled_) return {};
  return {localization_.truth, localization_.snapshots, localization_.particles, localization_.segments};
}

VisionStats& Telemetry::enable_vision() noexcept {
  vision_enabled_ = true;
  return vision_;
}

PlanTrack& Telemetry::enable_plans(const hal::PlanPicture& geometry, std::size_t cells, std::size_t plans,
                                   std::size_t points_per_plan) {
  plans_enabled_ = true;
  plans_.geometry = geometry;
  plans_.cells.reserve(cells);
  plans_.ends.reserve(plans);
  plans_.points.reserve(plans * points_per_plan);
  return plans_;
}

void Telemetry::record_map_cell(std::uint32_t cell) noexcept {
  if (plans_.cells.size() < plans_.cells.capacity()) {
    plans_.cells.push_back(cell);
  } else {
    ++plans_.dropped;
  }
}

void Telemetry::record_plan(std::span<const hal::WorldPoint> path) noexcept {
  if (plans_.ends.size() == plans_.ends.capacity() || plans_.points.size() + path.size() > plans_.points.capacity()) {
    ++plans_.dropped;
    return;
  }
  plans_.points.insert(plans_.points.end(), path.begin(), path.end());
  plans_.ends.push_back(static_cast<std::uint32_t>(plans_.points.size()));
  ++plans_.plans;
}

void Telemetry::extend_last_plan(const hal::WorldPoint& p) noexcept {
  if (plans_.ends.empty() || plans_.points.size() == plans_.points.capacity()) {
    ++plans_.dropped;
    return;
  }
  plans_.points.push_back(p);
  plans_.ends.back() = static_cast<std::uint32_t>(plans_.points.size());
}

void Telemetry::record_reported_obstacle(const hal::WorldPoint& p) noexcept {
  if (plans_.reported.size() == plans_.reported.capacity()) {
    ++plans_.dropped;
    return;
  }
  plans_.reported.push_back(p);
}

void Telemetry::record_missed_plans(std::uint64_t n) noexcept { plans_.missed_posts += n; }

hal::PlanPicture Telemetry::plan_picture() const noexcept {
  if (!plans_enabled_) return {};
  hal::PlanPicture p = plans_.geometry;
  p.occupied = plans_.cells;
  p.plan_points = plans_.points;
  p.plan_ends = plans_.ends;
  p.places = plans_.places;
  p.reported = plans_.reported;
  return p;
}

}  // namespace ringlet::firmware
