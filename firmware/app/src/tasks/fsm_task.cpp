#include "ringlet/firmware/tasks/fsm_task.hpp"

namespace ringlet::firmware {

std::unique_ptr<executive::Task> FsmTask::make(TaskServices& services) {
  return std::make_unique<FsmTask>(services.schedule);
}

void FsmTask::run(const executive::TaskContext& ctx) noexcept { schedule_.run_turn(ctx.now); }

hal::Nanos FsmTask::modelled_cost() const noexcept {
  std::int64_t ringlets = 0;
  for (std::size_t i = 0; i < schedule_.size(); ++i) ringlets += schedule_.ringlets_per_turn(i);
  return kTurnCost + ringlets * kRingletCost;
}

}  // namespace ringlet::firmware
