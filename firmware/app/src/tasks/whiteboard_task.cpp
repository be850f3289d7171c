#include "ringlet/firmware/tasks/whiteboard_task.hpp"

#include <algorithm>

#include "ringlet/executive/executive.hpp"

namespace ringlet::firmware {

std::unique_ptr<executive::Task> WhiteboardTask::make(TaskServices& services) {
  return std::make_unique<WhiteboardTask>(services.board, services.executive, services.message_log,
                                          services.remote_inbox);
}

void WhiteboardTask::run(const executive::TaskContext& ctx) noexcept {
  if (log_ != nullptr) log_->set_frame(ctx.frame);
  if (inbox_ != nullptr) (void)inbox_->deliver(board_);
  board_.dispatch();
  const auto per_second = static_cast<std::uint64_t>(std::chrono::seconds{1} / ctx.period);
  if (executive_ == nullptr || per_second == 0 || ctx.frame % per_second != 0) return;
  wb::ExecutiveTiming t{};
  const auto& frames = executive_->frame_stats();
  t.frames = frames.frames;
  t.frame_overruns = frames.frame_overruns;
  t.slips = frames.slips;
  const auto stats = executive_->task_stats();
  t.task_count = static_cast<std::uint16_t>(std::min(stats.size(), t.task_worst_ns.size()));
  for (std::size_t i = 0; i < t.task_count; ++i) t.task_worst_ns[i] = stats[i].wall.max().count();
  board_.post(t);
}

}  // namespace ringlet::firmware
