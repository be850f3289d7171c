#include "ringlet/firmware/tasks/whiteboard_task.hpp"

#include <algorithm>
#include <array>
#include <string_view>

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
  if (executive_ == nullptr || !ctx.first_frame_of_each(std::chrono::seconds{1})) return;
  wb::ExecutiveTiming t{};
  const auto& frames = executive_->frame_stats();
  t.frames = frames.frames;
  t.frame_overruns = frames.frame_overruns;
  t.slips = frames.slips;
  const auto stats = executive_->task_stats();
  const auto tasks = executive_->tasks();
  t.task_count = static_cast<std::uint16_t>(std::min(stats.size(), t.task_worst_ns.size()));
  std::array<char, decltype(t.task_names)::kCapacity> names{};  // "sense,vision,...", no allocation
  std::size_t used = 0;
  bool full = false;  // once a name does not fit, none after it is written (names stay in index order)
  for (std::size_t i = 0; i < t.task_count; ++i) {
    t.task_worst_ns[i] = stats[i].wall.max().count();
    t.task_every[i] = static_cast<std::uint16_t>(tasks[i].spec.every);
    t.task_budget_ns[i] = tasks[i].spec.budget.count();
    t.task_overruns[i] = stats[i].overruns;
    t.task_measured_overruns[i] = stats[i].measured_overruns;
    t.task_skipped[i] = stats[i].skipped;
    const std::string_view name = tasks[i].spec.name;
    full = full || used + (used > 0 ? 1 : 0) + name.size() > names.size();
    if (full) continue;
    if (used > 0) names[used++] = ',';
    std::copy(name.begin(), name.end(), names.begin() + static_cast<std::ptrdiff_t>(used));
    used += name.size();
  }
  (void)t.task_names.assign(std::string_view(names.data(), used));
  board_.post(t);
}

}  // namespace ringlet::firmware
