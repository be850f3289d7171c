#include "ringlet/executive/executive.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <utility>

namespace ringlet::executive {

namespace {

std::string join(const std::vector<std::string>& problems) {
  std::string text = "invalid task table:";
  for (const auto& p : problems) text += "\n  - " + p;
  return text;
}

std::vector<TaskSpec> specs_of(const std::vector<TaskBinding>& tasks) {
  std::vector<TaskSpec> specs;
  specs.reserve(tasks.size());
  for (const auto& t : tasks) specs.push_back(t.spec);
  return specs;
}

// Frames f in [0, n) with f % every == phase.
std::uint64_t activations_before(std::uint64_t n, const TaskSpec& t) noexcept {
  const auto every = static_cast<std::uint64_t>(t.every);
  const auto phase = static_cast<std::uint64_t>(t.phase);
  return n > phase ? (n - phase - 1) / every + 1 : 0;
}

}  // namespace

TableError::TableError(std::vector<std::string> problems)
    : std::runtime_error(join(problems)), problems_(std::move(problems)) {}

Executive::Executive(const ExecutiveConfig& config, std::vector<TaskBinding> tasks, hal::Clock& clock,
                     const hal::Stopwatch& stopwatch, hal::Actuators& safe_target, EventLog* events)
    : config_(config),
      tasks_(std::move(tasks)),
      stats_(tasks_.size()),
      clock_(clock),
      stopwatch_(stopwatch),
      safe_target_(safe_target),
      events_(events) {
  auto problems = validate(config_, specs_of(tasks_));
  for (const auto& t : tasks_) {
    if (t.task == nullptr) problems.push_back("task '" + t.spec.name + "' has no implementation bound to it");
  }
  if (tasks_.size() > std::numeric_limits<std::uint16_t>::max()) problems.push_back("too many tasks");
  if (!problems.empty()) throw TableError(std::move(problems));
}

StopReason Executive::run(std::uint64_t max_frames) noexcept {
  if (!started_) {
    start_ = clock_.now();
    started_ = true;
  }
  const std::uint64_t end_frame =
      max_frames == 0 ? std::numeric_limits<std::uint64_t>::max() : next_frame_ + max_frames;
  const std::int64_t period = config_.period.count();

  while (next_frame_ < end_frame && !stop_.load(std::memory_order_relaxed)) {
    const std::uint64_t frame = next_frame_;
    const Nanos due = start_ + Nanos{static_cast<std::int64_t>(frame) * period};
    clock_.sleep_until(due);
    frame_stats_.wake_latency.record(clock_.now() - due);
    heartbeat_.fetch_add(1, std::memory_order_release);

    run_frame(frame, due);

    const Nanos finished = clock_.now();
    frame_stats_.busy.record(finished - due);
    ++frame_stats_.frames;
    std::uint64_t next = frame + 1;
    if (finished > due + config_.period) {
      // Keep the phase: resume at the first frame that is not yet past due, never burst.
      const auto since_start = (finished - start_).count();
      next = static_cast<std::uint64_t>((since_start + period - 1) / period);
      ++frame_stats_.frame_overruns;
      frame_stats_.slips += next - (frame + 1);
      count_slipped_activations(frame + 1, next);
      if (frame_stats_.frame_overruns == 1 ||
          frame - last_frame_overrun_warn_ >= static_cast<std::uint64_t>(config_.warn_every_frames)) {
        last_frame_overrun_warn_ = frame;
        emit(Event{EventKind::kFrameOverrun, 0, frame, finished - due, config_.period, next - (frame + 1), 0});
      }
    }
    next_frame_ = next;
  }
  return stop_.load(std::memory_order_relaxed) ? StopReason::kRequested : StopReason::kFrameLimit;
}

void Executive::run_frame(std::uint64_t frame, Nanos frame_start) noexcept {
  for (std::size_t i = 0; i < tasks_.size(); ++i) {
    if (tasks_[i].spec.active_in(frame)) run_task(i, frame, frame_start);
  }
  if (observer_ != nullptr) observer_->frame_done(frame, frame_start);
}

void Executive::run_task(std::size_t index, std::uint64_t frame, Nanos frame_start) noexcept {
  const TaskBinding& binding = tasks_[index];
  TaskStats& s = stats_[index];
  if (s.skip_next) {
    s.skip_next = false;
    ++s.skipped;
    return;
  }

  TaskContext ctx;
  ctx.frame = frame;
  ctx.frame_start = frame_start;
  ctx.now = clock_.now();
  ctx.deadline = std::min(ctx.now + binding.spec.budget, frame_start + config_.period);
  ctx.period = config_.period;
  ctx.degrade_level = s.degrade_level;
  ctx.stopwatch = &stopwatch_;
  ctx.budget = ctx.deadline - ctx.now;
  ctx.stop_flag = &stop_;

  const Nanos cpu0 = stopwatch_.cpu_now();
  ctx.started_wall = stopwatch_.wall_now();
  binding.task->run(ctx);
  const Nanos wall = stopwatch_.wall_now() - ctx.started_wall;
  const Nanos cpu = stopwatch_.cpu_now() - cpu0;

  const Nanos modelled = binding.task->modelled_cost();

  ++s.runs;
  if (s.degrade_level > 0) ++s.degraded_runs;
  s.wall.record(wall);
  s.cpu.record(cpu);
  s.model.record(modelled);
  const Nanos measured = config_.overrun_on_cpu_time ? cpu : wall;
  if (measured > binding.spec.budget) ++s.measured_overruns;
  // In lockstep the host's speed must not steer the robot: the policy sees the modelled cost.
  const Nanos judged = config_.judge_on_model ? modelled : measured;
  if (judged > binding.spec.budget) {
    on_overrun(index, frame, judged);
  } else if (binding.task->overloaded()) {
    on_overload(index);
  } else {
    on_budget_met(index);
  }
}

void Executive::on_overrun(std::size_t index, std::uint64_t frame, Nanos measured) noexcept {
  const TaskSpec& spec = tasks_[index].spec;
  TaskStats& s = stats_[index];
  const auto task = static_cast<std::uint16_t>(index);
  ++s.overruns;
  s.clean_streak = 0;

  switch (spec.policy) {
    case OverrunPolicy::kWarn:
      break;
    case OverrunPolicy::kSkip:
      s.skip_next = true;
      break;
    case OverrunPolicy::kDegrade:
      if (s.degrade_level < config_.degrade_max_level) ++s.degrade_level;
      break;
    case OverrunPolicy::kFailsafe:
      safe_target_.enter_safe_state();
      if (!failsafe_triggered_) {
        failsafe_triggered_ = true;
        failsafe_task_ = static_cast<int>(index);
        emit(Event{EventKind::kFailsafe, task, frame, measured, spec.budget, 0, 0});
      }
      break;
  }

  // Rate-limited warning: the first overrun, then at most one per warn_every_frames.
  if (s.warned == 0 || frame - s.last_warn_frame >= static_cast<std::uint64_t>(config_.warn_every_frames)) {
    emit(Event{EventKind::kOverrun, task, frame, measured, spec.budget, s.suppressed_warnings, s.degrade_level});
    s.suppressed_warnings = 0;
    s.last_warn_frame = frame;
    ++s.warned;
  } else {
    ++s.suppressed_warnings;
  }
}

void Executive::on_overload(std::size_t index) noexcept {
  TaskStats& s = stats_[index];
  ++s.overloads;
  s.clean_streak = 0;
  if (tasks_[index].spec.policy == OverrunPolicy::kDegrade && s.degrade_level < config_.degrade_max_level) ++s.degrade_level;
}

void Executive::on_budget_met(std::size_t index) noexcept {
  TaskStats& s = stats_[index];
  if (s.degrade_level == 0) return;
  if (++s.clean_streak >= config_.degrade_recover_after) {
    --s.degrade_level;
    s.clean_streak = 0;
  }
}

void Executive::count_slipped_activations(std::uint64_t first, std::uint64_t end) noexcept {
  for (std::size_t i = 0; i < tasks_.size(); ++i) {
    const TaskSpec& t = tasks_[i].spec;
    stats_[i].skipped += activations_before(end, t) - activations_before(first, t);
  }
}

void Executive::emit(const Event& e) noexcept {
  if (events_ != nullptr) events_->push(e);
}

}  // namespace ringlet::executive
