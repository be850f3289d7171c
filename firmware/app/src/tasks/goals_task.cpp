#include "ringlet/firmware/tasks/goals_task.hpp"

namespace ringlet::firmware {

std::unique_ptr<executive::Task> GoalsTask::make(TaskServices& services) {
  const MissionSettings& mission = services.config.mission;
  wb::MissionGoals goals{};
  // The configuration refuses more goals than the message holds.
  goals.count = static_cast<std::uint8_t>(mission.goals.size());
  for (std::size_t i = 0; i < mission.goals.size(); ++i) {
    goals.x[i] = mission.goals[i].x;
    goals.y[i] = mission.goals[i].y;
  }
  goals.tolerance = mission.goal_tolerance;
  return std::make_unique<GoalsTask>(goals, services.board);
}

void GoalsTask::run(const executive::TaskContext& /*ctx*/) noexcept { board_.post(goals_); }

}  // namespace ringlet::firmware
