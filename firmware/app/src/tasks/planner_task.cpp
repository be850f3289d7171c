#include "ringlet/firmware/tasks/planner_task.hpp"

#include <algorithm>
#include <cmath>

namespace ringlet::firmware {

std::unique_ptr<executive::Task> PlannerTask::make(TaskServices& services) {
  return std::make_unique<PlannerTask>(services.config.planner, services.board,
                                       services.config.clock == ClockMode::kRealtime);
}

PlannerTask::PlannerTask(const PlannerSettings& settings, wb::Whiteboard& board, bool realtime_backstop)
    : settings_(settings),
      board_(board),
      realtime_backstop_(realtime_backstop),
      map_(settings.map),
      model_(settings.cost),
      graph_(map_, model_) {
  search_.reserve(graph_.vertex_count());
  path_.assign(static_cast<std::size_t>(graph_.vertex_count()), -1);
  plan_.map_origin_x = settings.map.origin_x;
  plan_.map_origin_y = settings.map.origin_y;
  plan_.map_resolution = settings.map.resolution;
  plan_.map_width = static_cast<std::uint16_t>(settings.map.width_cells);
  plan_.map_height = static_cast<std::uint16_t>(settings.map.height_cells);
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
  // Feet in the robot frame (x ahead, y left) to the world: ahead is (sin θ, cos θ), left (−cos θ, sin θ).
  const double s = std::sin(pose.theta), c = std::cos(pose.theta);
  for (std::size_t i = 0; i < std::min<std::size_t>(d.count, d.foot_x.size()); ++i)
    mark(pose.x + d.foot_x[i] * s - d.foot_y[i] * c, pose.y + d.foot_x[i] * c + d.foot_y[i] * s);
}

void PlannerTask::run(const executive::TaskContext& ctx) noexcept {
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
    post_plan(planning::SearchStatus::kIdle, mission);
  } else if (start < 0 || goal < 0) {
    searching_goal_ = false;  // the robot or the target lies outside the map: no way to plan
    post_plan(planning::SearchStatus::kUnreachable, mission);
  } else {
    const bool new_goal = !searching_goal_ || mission.target_x != plan_.goal_x || mission.target_y != plan_.goal_y;
    const int old_start = graph_.robot_region();
    graph_.set_robot_region(start);
    if (new_goal) {
      search_.begin(graph_, start, goal);
      searching_goal_ = true;
      plan_.has_plan = false;
      plan_.replans = 0;
      map_.clear_changes();
    } else {
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
    }
    planning::SearchStatus status = search_.status();
    std::int64_t left = settings_.pops_per_slice;
    while (left > 0) {
      const std::int64_t chunk = std::min<std::int64_t>(left, 64);
      status = search_.step(chunk);
      left -= chunk;
      if (status != planning::SearchStatus::kSearching) break;
      if (realtime_backstop_ && ctx.out_of_time()) break;  // the real clock's backstop only
    }
    post_plan(status, mission);
  }
  const std::int64_t pops = search_.counters().pops - pops_before;
  cost_ = kBaseCost + kCostPerBeam * beams + kCostPerPop * pops;
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
