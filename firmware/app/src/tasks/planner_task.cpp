#include "ringlet/firmware/tasks/planner_task.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "ringlet/planning/experience_file.hpp"
#include "ringlet/planning/movingai.hpp"

namespace ringlet::firmware {
namespace {

// Distinct feature vectors remembered per index: a 40 m map of 1 m regions has 12800 edges, most
// of them alike.
constexpr std::size_t kMemoCapacity = 4096;

std::unique_ptr<planning::KnnRegressor> make_knn(const PlannerSettings& s, std::span<const planning::Experience> loaded) {
  if (s.cost_model != CostModelKind::kKnn) return nullptr;
  auto knn = std::make_unique<planning::KnnRegressor>(s.knn);
  knn->reserve(loaded.size() + (s.learn_online ? static_cast<std::size_t>(s.capacity) : 0U));
  for (const planning::Experience& e : loaded) (void)knn->add(e.features, e.achieved_speed);
  (void)knn->rebuild();
  (void)knn->publish();
  return knn;
}

std::unique_ptr<planning::CostModel> make_model(const PlannerSettings& s, planning::KnnRegressor* knn) {
  if (knn == nullptr) return std::make_unique<planning::BinaryCostModel>(s.cost);
  return std::make_unique<planning::LearnedCostModel>(
      *knn, planning::LearnedCostParams{s.cost.top_speed, s.wall_occupied, kMemoCapacity}, s.map);
}

}  // namespace

std::unique_ptr<executive::Task> PlannerTask::make(TaskServices& services) {
  const PlannerSettings& p = services.config.planner;
  std::vector<planning::Experience> loaded;
  if (!p.experiences.empty()) {
    try {
      loaded = planning::load_experiences(p.experiences);
    } catch (const planning::ExperienceFileError& e) {
      throw ConfigError(services.config.positions.at("planner.experiences") + ": planner.experiences: " + e.what());
    }
  }
  std::optional<planning::MovingAiMap> prior;
  if (!p.prior_map.empty()) {
    const std::string where = services.config.positions.at("planner.prior_map") + ": planner.prior_map: ";
    try {
      prior = planning::read_movingai_map(p.prior_map);
    } catch (const planning::MovingAiError& e) {
      throw ConfigError(where + e.what());
    }
    if (prior->width != p.map.width_cells || prior->height != p.map.height_cells) {
      throw ConfigError(where + p.prior_map.string() + " is " + std::to_string(prior->width) + " x " +
                        std::to_string(prior->height) + " cells, the planner's grid " +
                        std::to_string(p.map.width_cells) + " x " + std::to_string(p.map.height_cells) +
                        " (width_cells x height_cells)");
    }
  }
  return std::make_unique<PlannerTask>(p, services.board, services.config.clock == ClockMode::kRealtime,
                                       services.experiences, loaded, prior ? &*prior : nullptr);
}

PlannerTask::PlannerTask(const PlannerSettings& settings, wb::Whiteboard& board, bool realtime, ExperienceLog* log,
                         std::span<const planning::Experience> loaded, const planning::MovingAiMap* prior)
    : settings_(settings),
      board_(board),
      realtime_(realtime),
      log_(settings.records() ? log : nullptr),
      map_(settings.map),
      knn_(make_knn(settings, loaded)),
      model_(make_model(settings, knn_.get())),
      learned_(dynamic_cast<planning::LearnedCostModel*>(model_.get())),
      graph_(map_, *model_),
      recorder_(settings.cost.top_speed) {
  if (prior != nullptr) mark_prior(*prior);
  search_.reserve(graph_.vertex_count());
  if (learned_ != nullptr) {
    reread_.assign(static_cast<std::size_t>(graph_.vertex_count()), -1);
    queued_.assign(static_cast<std::size_t>(graph_.vertex_count()), 0);
  }
  path_.assign(static_cast<std::size_t>(graph_.vertex_count()), -1);
  if (knn_ && settings.learn_online) worker_ = std::make_unique<planning::RebuildWorker>(*knn_);
  stored_at_request_ = knn_ ? knn_->stored() : 0;
  plan_.map_origin_x = settings.map.origin_x;
  plan_.map_origin_y = settings.map.origin_y;
  plan_.map_resolution = settings.map.resolution;
  plan_.map_width = static_cast<std::uint16_t>(settings.map.width_cells);
  plan_.map_height = static_cast<std::uint16_t>(settings.map.height_cells);
}

void PlannerTask::mark_prior(const planning::MovingAiMap& prior) {
  // The file's first row is the grid's north edge (a map reads like a picture); cell row 0 is the
  // south edge (the grid's origin is its south-west corner).
  for (int row = 0; row < prior.height; ++row) {
    for (int x = 0; x < prior.width; ++x) {
      if (!prior.passable(x, row)) (void)map_.mark_cell(x, prior.height - 1 - row);
    }
  }
  map_.clear_changes();  // known before the first search: nothing to repair
}

void PlannerTask::mark(double wx, double wy) noexcept {
  int cx = 0, cy = 0;
  if (!map_.cell_of(wx, wy, cx, cy) || !map_.mark_cell(cx, cy)) return;
  if (plan_.new_cell_count < plan_.new_cells.size()) {
    plan_.new_cells[plan_.new_cell_count++] = static_cast<std::uint32_t>(cy * settings_.map.width_cells + cx);
  } else {
    ++plan_.new_cells_dropped;
  }
}

int PlannerTask::integrate_scan(const wb::Pose& pose) noexcept {
  // The scan as hal::LaserScan would give it, without copying one: beam i at angle_min + i·inc.
  const std::size_t beams = std::min<std::size_t>(scan_.beam_count, scan_.range_mm.size());
  for (std::size_t i = 0; i < beams; ++i) {
    if (scan_.range_mm[i] == 0) continue;  // phi: nothing seen, nothing marked
    const double bearing = pose.theta + scan_.angle_min + static_cast<double>(i) * scan_.angle_increment;
    const double r = scan_.range_mm[i] * 1e-3;
    mark(pose.x + r * std::sin(bearing), pose.y + r * std::cos(bearing));
  }
  return static_cast<int>(beams);
}

void PlannerTask::integrate_robots(const wb::Pose& pose) noexcept {
  const std::uint64_t gen = board_.generation<wb::RobotDetections>();
  if (gen == robots_seen_) return;  // none posted since (or no vision in the table)
  robots_seen_ = gen;
  const wb::RobotDetections d = board_.get<wb::RobotDetections>();
  // Feet in the robot frame (x ahead, y left) to the world.
  const hal::RobotToWorld to_world(hal::Pose2{pose.x, pose.y, pose.theta});
  for (std::size_t i = 0; i < std::min<std::size_t>(d.count, d.foot_x.size()); ++i) {
    const hal::WorldPoint foot = to_world.point(d.foot_x[i], d.foot_y[i]);
    mark(foot.x, foot.y);
  }
}

void PlannerTask::record(const wb::Pose& pose, int region, const executive::TaskContext& ctx) noexcept {
  const wb::MotionCommand command = board_.get<wb::MotionCommand>();  // the last frame's, after Safety
  planning::TransitionSample sample;
  sample.region = region;
  sample.x = pose.x;
  sample.y = pose.y;
  sample.time_ns = ctx.frame_start.count();
  sample.frame = ctx.frame;
  sample.commanded_speed = command.stop ? 0.0 : command.velocity;
  sample.leg = leg_;
  planning::Experience e;
  if (!recorder_.observe(graph_, sample, e)) return;
  ++recorded_;
  if (log_ != nullptr) (void)log_->add(e);
  if (worker_) (void)knn_->add(e.features, e.achieved_speed);
}

void PlannerTask::forget_changes(int old_robot_region, int robot_region, bool repair) noexcept {
  if (old_robot_region != robot_region) {
    learned_->edges_from_changed(old_robot_region);
    learned_->edges_from_changed(robot_region);
    if (repair) {
      queue_reread(old_robot_region);
      queue_reread(robot_region);
    }
  }
  for (const int r : map_.changed_regions()) {
    const std::size_t n = learned_->region_changed(r, sources_);
    if (!repair) continue;
    for (std::size_t i = 0; i < n; ++i) queue_reread(sources_[i]);
  }
  map_.clear_changes();
  if (!repair) {  // a new search reads every cost afresh
    for (; reread_count_ > 0; --reread_count_, reread_head_ = (reread_head_ + 1) % reread_.size())
      queued_[static_cast<std::size_t>(reread_[reread_head_])] = 0;
  }
}

void PlannerTask::queue_reread(int v) noexcept {
  if (v < 0 || queued_[static_cast<std::size_t>(v)] != 0) return;
  queued_[static_cast<std::size_t>(v)] = 1;
  reread_[(reread_head_ + reread_count_++) % reread_.size()] = v;  // at most one entry per vertex
}

std::int64_t PlannerTask::drain(std::int64_t units) noexcept {
  const std::uint64_t p0 = learned_->predictions();
  std::int64_t done = 0, spent = 0;
  while (reread_count_ > 0 && spent < units) {
    const int v = reread_[reread_head_];
    reread_head_ = (reread_head_ + 1) % reread_.size();
    --reread_count_;
    queued_[static_cast<std::size_t>(v)] = 0;
    search_.edges_changed(v);
    ++done;
    spent = done + static_cast<std::int64_t>(learned_->predictions() - p0) * kPopsPerPrediction;
  }
  rereads_ += done;
  return spent;
}

std::int64_t PlannerTask::learn(std::int64_t units) noexcept {
  if (!worker_) return 0;
  switch (learning_) {
    case Learning::kIdle:
      if (activations_ % static_cast<std::uint64_t>(settings_.publish_every) == 0 && knn_->stored() > stored_at_request_) {
        stored_at_request_ = knn_->stored();
        requested_at_ = activations_;
        worker_->request(stored_at_request_);
        learning_ = Learning::kRebuilding;
      }
      return 0;
    case Learning::kRebuilding:
      // Lockstep: exactly the activation after the request, waiting for the worker if the host is
      // slow (virtual time stands still meanwhile). The real clock never waits.
      if (realtime_ && !worker_->idle()) return 0;
      worker_->wait_idle();
      (void)learned_->begin_refresh();
      learning_ = Learning::kRefreshing;
      break;
    case Learning::kRefreshing:
      break;
  }
  // Half the slice at most: the search goes on meanwhile, with the old costs. A prediction is
  // kPopsPerPrediction units, an edge visited kCostPerRefreshEdge / kCostPerPop.
  const std::int64_t share = std::max<std::int64_t>(units / 2, kPopsPerPrediction);
  const std::int64_t edges_per_unit = kCostPerPop / kCostPerRefreshEdge;
  const std::uint64_t p0 = learned_->predictions(), e0 = learned_->refresh_edges();
  const bool done = learned_->refresh(graph_, share / kPopsPerPrediction, share * edges_per_unit);
  std::int64_t spent = static_cast<std::int64_t>(learned_->predictions() - p0) * kPopsPerPrediction +
                       static_cast<std::int64_t>(learned_->refresh_edges() - e0) / edges_per_unit;
  if (done) {
    const std::uint64_t p1 = learned_->predictions();
    for (const int v : learned_->finish_refresh()) queue_reread(v);  // re-read under later budgets
    switched_ = static_cast<std::int64_t>(learned_->edge_count());
    spent += static_cast<std::int64_t>(learned_->predictions() - p1) * kPopsPerPrediction;
    ++publishes_;
    learning_ = Learning::kIdle;
  }
  return spent;
}

planning::SearchStatus PlannerTask::search(const executive::TaskContext& ctx, std::int64_t units) noexcept {
  planning::SearchStatus status = search_.status();
  if (learned_ == nullptr) {
    std::int64_t left = units;
    while (left > 0) {
      const std::int64_t chunk = std::min<std::int64_t>(left, 64);
      status = search_.step(chunk);
      left -= chunk;
      if (status != planning::SearchStatus::kSearching) break;
      if (realtime_ && ctx.out_of_time()) break;  // the real clock's backstop only
    }
    return status;
  }
  // Pop by pop: a pop may make predictions (up to 64, typically none or a few: the memo), and the
  // slice ends while a pop's usual predictions still fit.
  const std::int64_t pops0 = search_.counters().pops;
  const std::uint64_t predictions0 = learned_->predictions();
  for (std::int64_t n = 0;; ++n) {
    const std::int64_t spent = (search_.counters().pops - pops0) +
                               static_cast<std::int64_t>(learned_->predictions() - predictions0) * kPopsPerPrediction;
    if (spent + kPopReserve >= units) break;  // room left for the predictions of one more pop
    status = search_.step(1);
    if (status != planning::SearchStatus::kSearching) break;
    if (realtime_ && n % 64 == 63 && ctx.out_of_time()) break;
  }
  return status;
}

void PlannerTask::run(const executive::TaskContext& ctx) noexcept {
  ++activations_;
  recorded_ = 0;
  switched_ = 0;
  rereads_ = 0;
  const std::uint64_t predictions_before = learned_ ? learned_->predictions() : 0;
  const std::uint64_t refresh_before = learned_ ? learned_->refresh_edges() : 0;
  const wb::Pose pose = board_.get<wb::Pose>();
  const wb::MissionStatus mission = board_.get<wb::MissionStatus>();
  scan_ = board_.get<wb::LaserScan>();
  int beams = 0;
  plan_.new_cell_count = 0;  // this activation's new cells only (the dropped count runs on)
  if (pose.valid) {
    beams = integrate_scan(pose);
    integrate_robots(pose);
  }
  const std::int64_t pops_before = search_.counters().pops;
  const int start = pose.valid ? map_.region_at(pose.x, pose.y) : -1;
  const int goal = map_.region_at(mission.target_x, mission.target_y);

  if (!pose.valid || mission.goal_count == 0 || mission.done) {
    searching_goal_ = false;
    recorder_.reset();
    (void)learn(settings_.pops_per_slice);
    post_plan(planning::SearchStatus::kIdle, mission);
  } else if (start < 0 || goal < 0) {
    searching_goal_ = false;  // the robot or the target lies outside the map: no way to plan
    recorder_.reset();
    (void)learn(settings_.pops_per_slice);
    post_plan(planning::SearchStatus::kUnreachable, mission);
  } else {
    const bool new_goal = !searching_goal_ || mission.target_x != plan_.goal_x || mission.target_y != plan_.goal_y;
    if (new_goal) ++leg_;
    const int old_start = graph_.robot_region();
    graph_.set_robot_region(start);
    if (settings_.records()) record(pose, start, ctx);
    if (new_goal) {
      if (learned_) forget_changes(old_start, start, false);
      search_.begin(graph_, start, goal);
      searching_goal_ = true;
      plan_.has_plan = false;
      plan_.replans = 0;
      map_.clear_changes();
    } else if (learned_ == nullptr) {
      if (start != search_.start()) {
        search_.move_start(start);
        search_.vertex_changed(old_start);  // its own count counts again
        search_.vertex_changed(start);
      }
      if (!map_.changed_regions().empty()) {
        for (const int r : map_.changed_regions()) search_.vertex_changed(r);
        map_.clear_changes();
        if (plan_.has_plan) ++plan_.replans;
      }
    } else {
      if (start != search_.start()) search_.move_start(start);
      const bool changed = !map_.changed_regions().empty();
      forget_changes(old_start, start, true);
      if (changed && plan_.has_plan) ++plan_.replans;
    }
    std::int64_t units = settings_.pops_per_slice;
    if (learned_ != nullptr) {
      units -= drain(units);
      units -= learn(units);
    }
    const bool stale = learned_ != nullptr && reread_count_ > 0;
    post_plan(stale ? planning::SearchStatus::kSearching : search(ctx, units), mission);
  }
  const std::int64_t pops = search_.counters().pops - pops_before;
  cost_ = kBaseCost + kCostPerBeam * beams + kCostPerPop * pops + kCostPerExperience * recorded_;
  if (learned_) {
    cost_ += kCostPerPrediction * static_cast<std::int64_t>(learned_->predictions() - predictions_before) +
             kCostPerRefreshEdge * static_cast<std::int64_t>(learned_->refresh_edges() - refresh_before) +
             kCostPerSwitchedEdge * switched_ + kCostPerPop * rereads_;
  }
}

void PlannerTask::post_plan(planning::SearchStatus status, const wb::MissionStatus& mission) noexcept {
  plan_.goal_x = mission.target_x;
  plan_.goal_y = mission.target_y;
  plan_.occupied_cells = static_cast<std::uint32_t>(map_.occupied_cells());
  plan_.expansions = static_cast<std::uint64_t>(search_.counters().expansions);
  switch (status) {
    case planning::SearchStatus::kIdle:
      plan_.status = wb::PlanStatus::kIdle;
      plan_.has_plan = false;
      break;
    case planning::SearchStatus::kUnreachable:
      plan_.status = wb::PlanStatus::kUnreachable;
      plan_.has_plan = false;
      break;
    case planning::SearchStatus::kSearching:
      plan_.status = wb::PlanStatus::kSearching;  // the last ready plan (if any) stays as it was
      break;
    case planning::SearchStatus::kReady: {
      plan_.status = wb::PlanStatus::kReady;
      const int n = search_.extract_path(path_);
      if (n <= 0) {  // cannot happen for a ready search; never post half a plan
        plan_.status = wb::PlanStatus::kSearching;
        break;
      }
      plan_.has_plan = true;
      plan_.expected_s = planning::RegionGraph::seconds(search_.plan_cost());
      plan_.path_count = static_cast<std::uint16_t>(std::min<std::size_t>(static_cast<std::size_t>(n), plan_.path_x.size()));
      for (std::size_t i = 0; i < plan_.path_count; ++i) {
        const hal::Pose2 c = map_.region_centre(path_[i]);
        plan_.path_x[i] = c.x;
        plan_.path_y[i] = c.y;
      }
      if (n > 2) {
        plan_.waypoint_x = plan_.path_x[1];
        plan_.waypoint_y = plan_.path_y[1];
      } else {  // the next region (or this one) is the target's: the target itself
        plan_.waypoint_x = mission.target_x;
        plan_.waypoint_y = mission.target_y;
      }
      break;
    }
  }
  board_.post(plan_);
}

}  // namespace ringlet::firmware
