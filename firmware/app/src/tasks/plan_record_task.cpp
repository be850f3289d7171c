#include "ringlet/firmware/tasks/plan_record_task.hpp"

#include <algorithm>

namespace ringlet::firmware {

std::unique_ptr<executive::Task> PlanRecordTask::make(TaskServices& services) {
  const planning::MapConfig& m = services.config.planner.map;
  hal::PlanPicture geometry;
  geometry.origin = {m.origin_x, m.origin_y};
  geometry.cell = m.resolution;
  geometry.width_cells = m.width_cells;
  geometry.height_cells = m.height_cells;
  geometry.region_cells = m.region_cells;
  const auto cells = static_cast<std::size_t>(m.width_cells) * static_cast<std::size_t>(m.height_cells);
  services.telemetry.enable_plans(geometry, cells, kMaxPlans, wb::Plan{}.path_x.size());
  return std::make_unique<PlanRecordTask>(services.telemetry, services.board);
}

void PlanRecordTask::record(const wb::Plan& plan) noexcept {
  for (std::size_t i = 0; i < std::min<std::size_t>(plan.new_cell_count, plan.new_cells.size()); ++i)
    telemetry_.record_map_cell(plan.new_cells[i]);
  if (plan.status != wb::PlanStatus::kReady || !plan.has_plan) return;
  const bool new_goal = !have_last_ || plan.goal_x != last_goal_x_ || plan.goal_y != last_goal_y_;
  if (!new_goal && plan.replans == last_replans_) return;  // the same plan, one region further on
  have_last_ = true;
  last_goal_x_ = plan.goal_x;
  last_goal_y_ = plan.goal_y;
  last_replans_ = plan.replans;
  const std::size_t n = std::min<std::size_t>(plan.path_count, path_.size());
  for (std::size_t i = 0; i < n; ++i) path_[i] = {plan.path_x[i], plan.path_y[i]};
  telemetry_.record_plan(std::span<const hal::WorldPoint>(path_.data(), n));
}

void PlanRecordTask::run(const executive::TaskContext& /*ctx*/) noexcept {
  board_.read_since<wb::Plan>(
      seen_, [this](const wb::Plan& plan) { record(plan); },
      [this](std::uint64_t n) { telemetry_.record_missed_plans(n); });
}

}  // namespace ringlet::firmware
