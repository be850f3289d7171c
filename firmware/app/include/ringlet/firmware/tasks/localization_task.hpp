#pragma once
// Self-localization (issue 17): odometry (BodyState) and what vision saw of the field (FieldLines:
// ground segments, the centre circle) → the particle filter of localization/ → Pose (valid only
// when the estimate is neither lost nor ambiguous) and Localization (the estimate with its
// covariance, mirror, quality and flags). For a robot without GPS: run it with `sense_no_gps`.
//
// Every activation dead-reckons the odometry and keeps the last kRing odometry poses by stamp;
// a new FieldLines message is taken from the robot frame at its capture (a frame or two ago)
// into the robot frame of now by the odometry between the two, so the camera's latency does not
// bend the correction. The filter is moved by the odometry since the last activation that moved
// it, then corrected. Everything is sized in make(); run() allocates nothing.
//
// For the run's picture it records snapshots into Telemetry (an observer: nothing it records is
// read back): the particles and the observed segments, taken into the world with the estimate,
// at the first correction, at each relocalization, at a correction that moves the estimate by
// more than kJumpM or kJumpRad (at most one a second), and after kSnapshotEvery without one; at
// most kMaxSnapshots, sized at start-up.
#include <array>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"
#include "ringlet/localization/particle_filter.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

class LocalizationTask final : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{"localization", kTypeNames<wb::BodyState, wb::FieldLines>,
                                                kTypeNames<wb::Pose, wb::Localization>, here()};
  /// The modelled cost: a fixed part, per particle moved and per observation point evaluated for
  /// a particle (the host's time in ringlet_bench_localization × the board slowdown of 4 that
  /// vision's cost model assumes). Measured here (2026-12-04, 300 particles): BM_Predict 95 ns per
  /// particle, BM_Correct 56–65 ns per term, the whole correction (resampling, clusters,
  /// estimate) spread over its terms.
  static constexpr hal::Nanos kModelledBase{20'000};
  static constexpr double kModelledNsPerParticleMoved = 4 * 100.0;
  static constexpr double kModelledNsPerTerm = 4 * 60.0;
  static constexpr std::size_t kRing = 64;  // odometry poses kept: 0.64 s at 100 Hz
  static constexpr std::size_t kMaxSnapshots = 40;
  static constexpr hal::Nanos kSnapshotEvery{5'000'000'000};
  static constexpr hal::Nanos kMinJumpGap{1'000'000'000};
  static constexpr double kJumpM = 0.3;
  static constexpr double kJumpRad = 0.35;  // 20°

  static std::unique_ptr<executive::Task> make(TaskServices& services);
  /// `telemetry`: where the snapshots go (null: none are taken).
  LocalizationTask(wb::Whiteboard& board, const LocalizationSettings& settings, Telemetry* telemetry = nullptr);
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] hal::Nanos modelled_cost() const noexcept override { return cost_; }

  [[nodiscard]] const localization::ParticleFilter& filter() const noexcept { return filter_; }

 private:
  struct Stamped {
    std::int64_t stamp_ns = 0;
    hal::Pose2 odometry{};
  };
  [[nodiscard]] hal::Pose2 odometry_at(std::int64_t stamp_ns) const noexcept;
  void post(std::int64_t stamp_ns) noexcept;
  void snapshot(hal::Nanos when, std::string_view reason, const localization::Observations& obs) noexcept;

  wb::Whiteboard& board_;
  localization::FieldModel field_;
  localization::ParticleFilter filter_;
  double side_;
  localization::OdometryIntegrator odometry_{};
  hal::Pose2 filter_odometry_{};  // the odometry pose the filter was last moved to
  std::array<Stamped, kRing> ring_{};
  std::size_t ring_count_ = 0, ring_next_ = 0;
  std::uint64_t last_lines_ = 0;
  std::uint64_t observations_ = 0;
  std::uint64_t lost_frames_ = 0;
  hal::Nanos cost_{0};
  Telemetry* telemetry_;
  std::vector<hal::Pose2> snapshot_particles_;        // sized in the constructor
  std::array<hal::WorldSegment, localization::Observations::kMaxLines> snapshot_segments_{};
  bool have_snapshot_ = false;
  hal::Nanos last_snapshot_{0};
  std::uint64_t snapshot_relocalizations_ = 0;
};

}  // namespace ringlet::firmware
