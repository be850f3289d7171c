#pragma once
// The record of a run, as the controller saw it: the trajectory (sampled every N frames), where
// the bumper touched something, the odometry's path length, the mission's progress and what
// vision found. Ground truth is not here: the report reads it from hal::GroundTruth. Buffers are sized at start-up for the longest run the
// configuration allows, so recording never allocates; samples beyond capacity are counted, not
// stored.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "ringlet/executive/histogram.hpp"
#include "ringlet/hal/geometry.hpp"
#include "ringlet/hal/ground_truth.hpp"
#include "ringlet/hal/time.hpp"
#include "ringlet/vision/stages.hpp"

namespace ringlet::firmware {

/// What vision did over the run.
struct VisionStats {
  std::uint64_t frames = 0;         // camera frames processed
  std::uint64_t with_lines = 0;     // ... in which at least one line was found
  std::uint64_t lines = 0;          // lines found in all
  std::uint64_t with_ball = 0;      // ... in which the ball was found
  std::uint64_t robots = 0;         // robot detections (verified or not) in all
  std::uint64_t cut = 0;            // ... in which the deadline cut work short
  std::uint64_t lines_cut = 0;      // ... in which it cut the line search (the task was overloaded)
  std::uint64_t degraded = 0;       // ... processed at a degrade level above 0
  std::uint64_t bad_frames = 0;     // frames of the wrong size (nothing done)
  std::uint64_t missed_frames = 0;  // sequence gaps: frames the camera had that were never processed
  // Per processed frame, each pipeline stage's modelled board time (vision::Stage order): where the
  // budget goes. Observed only: neither the run hash nor any decision reads it.
  std::array<executive::DurationHistogram, vision::kStageCount> stage_model{};
};

/// The planner's map and plans over the run (PlanRecordTask fills it): every cell the planner
/// marked occupied, and the plans worth drawing — the first plan to each goal and every plan after
/// a replan.
struct PlanTrack {
  hal::PlanPicture geometry{};  // origin, cell size and counts; the spans are set when drawn
  std::vector<std::uint32_t> cells;
  std::vector<hal::WorldPoint> points;
  std::vector<std::uint32_t> ends;
  std::vector<hal::NamedPoint> places;      // the names point into the configuration
  std::vector<hal::WorldPoint> reported;    // obstacles reported to the planner
  std::uint64_t plans = 0;          // plans recorded
  std::uint64_t dropped = 0;        // cells or plans that did not fit (counted, not stored)
  std::uint64_t missed_posts = 0;   // Plan generations overwritten before they were read
};

/// The localization over the run, for the picture: the true pose beside the estimate (the truth
/// scorer records it, at the trajectory's cadence) and snapshots of the filter (the localization
/// task records them: at its first correction, at each relocalization or large correction, and
/// every few seconds), all in buffers sized at start-up.
struct LocalizationTrack {
  std::vector<hal::Pose2> truth;
  std::vector<hal::LocalizationSnapshot> snapshots;
  std::vector<hal::Pose2> particles;
  std::vector<hal::WorldSegment> segments;
  std::uint64_t dropped_truth = 0;      // true poses that did not fit
  std::uint64_t dropped_snapshots = 0;  // snapshots that did not fit
};

class Telemetry {
 public:
  Telemetry(std::size_t trajectory_capacity, std::size_t collision_capacity);

  void record_pose(const hal::Pose2& pose) noexcept;
  void record_collision(const hal::Pose2& pose) noexcept;
  /// The odometry's signed distance so far; the path length grows by each change's magnitude.
  void record_odometry(double distance) noexcept;
  /// `frame`: the frame of this report; a goal newly reached is stamped with it (goal_frames()).
  void record_progress(std::size_t goals_reached, std::size_t goal_count, std::uint64_t frame) noexcept;
  /// Start-up only: the vision task's counters (the report shows them when enabled).
  VisionStats& enable_vision() noexcept;
  /// Start-up only (allocates): room for `cells` occupied cells and `plans` plans of up to
  /// `points_per_plan` points.
  PlanTrack& enable_plans(const hal::PlanPicture& geometry, std::size_t cells, std::size_t plans, std::size_t points_per_plan);
  void record_map_cell(std::uint32_t cell) noexcept;
  void record_plan(std::span<const hal::WorldPoint> path) noexcept;
  /// Extends the last plan recorded by one point (a task plan drawn as its actions come).
  void extend_last_plan(const hal::WorldPoint& p) noexcept;
  void record_reported_obstacle(const hal::WorldPoint& p) noexcept;
  void record_missed_plans(std::uint64_t n) noexcept;
  [[nodiscard]] const PlanTrack* plans() const noexcept { return plans_enabled_ ? &plans_ : nullptr; }
  /// The map and the plans for the picture (an empty PlanPicture without a planner).
  [[nodiscard]] hal::PlanPicture plan_picture() const noexcept;

  /// Start-up only (allocates): room for `snapshots` snapshots of up to `particles` particles and
  /// `segments` segments each (the true trajectory gets the estimated one's capacity).
  LocalizationTrack& enable_localization(std::size_t snapshots, std::size_t particles, std::size_t segments);
  void record_true_pose(const hal::Pose2& pose) noexcept;
  /// Room for one more snapshot of `particles` particles and `segments` segments?
  [[nodiscard]] bool snapshot_fits(std::size_t particles, std::size_t segments) const noexcept;
  /// Records a snapshot (counted as dropped when it does not fit).
  void record_snapshot(double time_s, const hal::Pose2& estimate, std::string_view reason,
                       std::span<const hal::Pose2> particles, std::span<const hal::WorldSegment> segments) noexcept;
  [[nodiscard]] const LocalizationTrack* localization() const noexcept {
    return localization_enabled_ ? &localization_ : nullptr;
  }
  /// The true trajectory and the snapshots for the picture (empty without localization).
  [[nodiscard]] hal::LocalizationPicture localization_picture() const noexcept;

  [[nodiscard]] std::span<const hal::Pose2> trajectory() const noexcept { return trajectory_; }
  [[nodiscard]] std::span<const hal::WorldPoint> collision_points() const noexcept { return collision_points_; }
  [[nodiscard]] std::uint64_t collisions() const noexcept { return collisions_; }
  /// Trajectory samples that did not fit the buffer (reported, never silently lost).
  [[nodiscard]] std::uint64_t dropped_samples() const noexcept { return dropped_; }
  [[nodiscard]] double odometry_path() const noexcept { return odometry_path_; }
  [[nodiscard]] std::size_t goals_reached() const noexcept { return goals_reached_; }
  [[nodiscard]] std::size_t goal_count() const noexcept { return goal_count_; }
  /// The frame in which each goal reached so far was first reported reached, in goal order (at
  /// most kMaxGoalFrames): per-goal mission times for the experiments.
  static constexpr std::size_t kMaxGoalFrames = 32;
  [[nodiscard]] std::span<const std::uint64_t> goal_frames() const noexcept {
    return {goal_frames_.data(), goals_stamped_};
  }
  [[nodiscard]] const VisionStats* vision() const noexcept { return vision_enabled_ ? &vision_ : nullptr; }

 private:
  std::vector<hal::Pose2> trajectory_;
  std::vector<hal::WorldPoint> collision_points_;
  std::uint64_t collisions_ = 0;
  std::uint64_t dropped_ = 0;
  bool have_odometry_ = false;
  double last_odometry_ = 0.0;
  double odometry_path_ = 0.0;
  std::size_t goals_reached_ = 0;
  std::size_t goal_count_ = 0;
  std::array<std::uint64_t, kMaxGoalFrames> goal_frames_{};
  std::size_t goals_stamped_ = 0;
  bool vision_enabled_ = false;
  VisionStats vision_{};
  bool plans_enabled_ = false;
  PlanTrack plans_{};
  bool localization_enabled_ = false;
  std::size_t trajectory_capacity_ = 0;
  LocalizationTrack localization_{};
};

}  // namespace ringlet::firmware
