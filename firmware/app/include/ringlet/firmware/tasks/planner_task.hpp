#pragma once
// The deliberative layer in the cycle (Powers & Balch §III-B): the laser scan goes into the
// occupancy grid through the pose, and D* Lite plans over the map's regions to the mission's
// current target (MissionStatus, posted by the Navigate machine), in slices.
//
// Each activation marks the newest scan (and the feet of the robots vision saw since the last
// activation, when the table runs vision: obstacles as laser hits are), tells D* Lite where the robot now is and which regions
// changed, and resumes the search for at most [planner] pops_per_slice queue pops: a
// deterministic amount of work, so a lockstep run is a pure function of seed and configuration.
// On the real clock the activation's deadline is a backstop, checked every 64 pops. A plan becomes
// visible (Plan, status ready) in the activation whose slice finishes it; until then the last
// ready plan's waypoint and path stay posted (has_plan), and a search that finds no way posts
// unreachable with no plan. The waypoint is the centre of the next region on the plan (the
// paper's transition model), or the target itself when the next region is the target's (or the
// robot is in it already): aiming at that region's centre first would overshoot the target.
//
// The learned cost model ([planner] cost_model = "knn", §III-C; planning/README.md): edges cost
// distance ÷ the kNN prediction, cached per edge. A changed region's edges are the ones whose
// features read it (two regions around), so D* Lite re-reads the edges of every vertex they leave
// (edges_changed) instead of a region's ring. A slice is then counted in work units: a pop or a
// vertex re-read is one, a kNN prediction kPopsPerPrediction (the ratio of their modelled costs).
// The vertices to re-read are queued and handed to D* Lite first, then the refresh after a
// publish has its share, then the search goes pop by pop, until pops_per_slice units are spent:
// a count as deterministic as the pops alone. The search does not step while re-reads are queued.
//
// Experiences ([planner] record, learn_online): each transition into an adjacent region is one
// (planning/transition_recorder.hpp), kept in the ExperienceLog; with learn_online it also joins
// the kNN store. Every publish_every activations, if new experiences arrived, a RebuildWorker
// rebuilds the index off the cycle. The next activation (lockstep: exactly that one, waiting for
// the worker if it is late, as virtual time allows; on the real clock: the first one that finds
// the rebuild done, never waiting) starts the sliced recomputation of every cached edge with the
// new index; the old costs stay in force until it has finished, then the new ones are switched in
// at once and the changed edges go to D* Lite's incremental repair.
//
// Everything (grid, regions, the search's arrays, the path, the caches, the stores) is sized at
// start-up from [planner].
#include <array>
#include <memory>
#include <span>
#include <vector>

#include "ringlet/executive/task.hpp"
#include "ringlet/firmware/experience_log.hpp"
#include "ringlet/firmware/task_declaration.hpp"
#include "ringlet/firmware/task_services.hpp"
#include "ringlet/planning/dstar_lite.hpp"
#include "ringlet/planning/knn_regressor.hpp"
#include "ringlet/planning/learned_cost_model.hpp"
#include "ringlet/planning/movingai.hpp"
#include "ringlet/planning/rebuild_worker.hpp"
#include "ringlet/planning/region_graph.hpp"
#include "ringlet/planning/transition_recorder.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::firmware {

class PlannerTask final : public executive::Task {
 public:
  static constexpr TaskDeclaration kDeclaration{"planner", kTypeNames<wb::Pose, wb::LaserScan, wb::MissionStatus>,
                                                kTypeNames<wb::Plan>, here(),
                                                kTypeNames<wb::RobotDetections, wb::MotionCommand>};
  /// The board's cost: a fixed part, every beam placed in the grid, every queue pop.
  static constexpr hal::Nanos kBaseCost{20'000};
  static constexpr hal::Nanos kCostPerBeam{100};
  static constexpr hal::Nanos kCostPerPop{800};
  /// The learned model's work: a kNN query (k = 5 over 5000 experiences: 10-21 us of CPU on the
  /// desktop, ringlet_bench_planning, planning/README.md; the upper end), an edge visited by the
  /// refresh after a publish (its features and a memo probe), the sweep that switches every cached
  /// edge, and an experience recorded (its features).
  static constexpr hal::Nanos kCostPerPrediction{20'000};
  static constexpr hal::Nanos kCostPerRefreshEdge{400};
  static constexpr hal::Nanos kCostPerSwitchedEdge{10};
  static constexpr hal::Nanos kCostPerExperience{2'000};
  static constexpr std::int64_t kPopsPerPrediction = kCostPerPrediction / kCostPerPop;
  /// The learned search stops this many units before the end of its slice: what a pop near new
  /// obstacles predicts (the worst, 64 predictions, is never met in the shipped worlds).
  static constexpr std::int64_t kPopReserve = 12 * kPopsPerPrediction;

  static std::unique_ptr<executive::Task> make(TaskServices& services);
  /// `log`: where recorded experiences go (null: none kept); `loaded`: the experiences the learned
  /// model starts from; `prior`: the cells known to be blocked before the run ([planner]
  /// prior_map, the grid's size; null: none), marked as laser hits would be.
  PlannerTask(const PlannerSettings& settings, wb::Whiteboard& board, bool realtime,
              ExperienceLog* log = nullptr, std::span<const planning::Experience> loaded = {},
              const planning::MovingAiMap* prior = nullptr);
  void run(const executive::TaskContext& ctx) noexcept override;
  [[nodiscard]] hal::Nanos modelled_cost() const noexcept override { return cost_; }

  [[nodiscard]] const planning::OccupancyGrid& map() const noexcept { return map_; }
  /// The learned model (null with the binary one) and its regressor.
  [[nodiscard]] const planning::LearnedCostModel* learned() const noexcept { return learned_; }
  [[nodiscard]] const planning::KnnRegressor* knn() const noexcept { return knn_.get(); }
  /// New indexes switched in so far (learn_online).
  [[nodiscard]] std::uint64_t publishes() const noexcept { return publishes_; }

 private:
  enum class Learning : std::uint8_t { kIdle, kRebuilding, kRefreshing };

  int integrate_scan(const wb::Pose& pose) noexcept;
  void integrate_robots(const wb::Pose& pose) noexcept;
  void mark(double wx, double wy) noexcept;
  void mark_prior(const planning::MovingAiMap& prior);
  void record(const wb::Pose& pose, int region, const executive::TaskContext& ctx) noexcept;
  /// The learned model forgets what the new counts and the robot's move changed; the vertices
  /// whose edges D* Lite must re-read are queued when `repair` (a search under way; else it starts
  /// afresh anyway).
  void forget_changes(int old_robot_region, int robot_region, bool repair) noexcept;
  void queue_reread(int v) noexcept;
  /// Hands queued vertices to D* Lite (each re-read may predict) for at most `units` work units;
  /// returns the units spent. The search does not step while any is queued: a plan is never
  /// finished on costs that are known to be out of date.
  std::int64_t drain(std::int64_t units) noexcept;
  /// learn_online: requests rebuilds, starts and slices the refresh, switches; returns the work
  /// units (pop equivalents) spent.
  std::int64_t learn(std::int64_t units) noexcept;
  planning::SearchStatus search(const executive::TaskContext& ctx, std::int64_t units) noexcept;
  void post_plan(planning::SearchStatus status, const wb::MissionStatus& mission) noexcept;

  PlannerSettings settings_;
  wb::Whiteboard& board_;
  bool realtime_;
  ExperienceLog* log_;
  planning::OccupancyGrid map_;
  std::unique_ptr<planning::KnnRegressor> knn_;  // cost_model = "knn" only
  std::unique_ptr<planning::CostModel> model_;
  planning::LearnedCostModel* learned_ = nullptr;
  planning::RegionGraph graph_;
  planning::DStarLite search_;
  std::unique_ptr<planning::RebuildWorker> worker_;  // learn_online only
  planning::TransitionRecorder recorder_;
  std::vector<int> path_;  // one entry per region: the longest path there can be
  std::array<int, planning::LearnedCostModel::kMaxSources> sources_{};
  std::vector<int> reread_;              // vertices D* Lite must re-read (learned model), FIFO ring
  std::vector<std::uint8_t> queued_;     // whether a vertex is in reread_
  std::size_t reread_head_ = 0, reread_count_ = 0;
  wb::LaserScan scan_{};
  wb::Plan plan_{};
  bool searching_goal_ = false;  // a search for plan_.goal_x/y has begun
  std::uint64_t robots_seen_ = 0;  // the last RobotDetections generation marked
  std::uint64_t leg_ = 0;          // targets planned for so far
  std::uint64_t activations_ = 0;
  Learning learning_ = Learning::kIdle;
  std::uint64_t requested_at_ = 0;       // the activation that asked for the rebuild
  std::size_t stored_at_request_ = 0;    // experiences in the store then
  std::uint64_t publishes_ = 0;
  std::int64_t recorded_ = 0;            // experiences recorded in this activation
  std::int64_t switched_ = 0;            // edges the switch to a new index swept in it
  std::int64_t rereads_ = 0;             // vertices handed to D* Lite in it (each like a pop)
  hal::Nanos cost_{kBaseCost};
};

}  // namespace ringlet::firmware
