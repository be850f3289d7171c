#pragma once
// Test doubles for the executive tests: a recording fake of hal::Actuators, a task whose cost is
// injected on a hal::VirtualClock (scriptable per frame or per activation), a stopwatch whose CPU
// time runs at half the wall rate, a rig that wires them into an Executive, and the frame grid the
// rigs run on (kStart, kPeriod, due, frames_where).
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ringlet/executive/event_log.hpp"
#include "ringlet/executive/executive.hpp"
#include "ringlet/executive/task.hpp"
#include "ringlet/executive/task_table.hpp"
#include "ringlet/hal/actuators.hpp"
#include "ringlet/hal/robot.hpp"
#include "ringlet/hal/virtual_clock.hpp"

namespace ringlet::executive::test {

using namespace std::chrono_literals;

/// Records writes and safe-state requests; honours the latch like a real backend. Thread-safe
/// for what the watchdog thread touches (enter_safe_state, in_safe_state).
class FakeActuators final : public hal::Actuators {
 public:
  void write(const hal::ActuatorCommand& cmd) noexcept override {
    if (safe_.load(std::memory_order_acquire)) {
      ignored_writes_.fetch_add(1, std::memory_order_relaxed);
      return;
    }
    last_ = cmd;
    writes_.fetch_add(1, std::memory_order_relaxed);
  }
  void enter_safe_state() noexcept override {
    safe_calls_.fetch_add(1, std::memory_order_relaxed);
    safe_.store(true, std::memory_order_release);
  }
  [[nodiscard]] bool in_safe_state() const noexcept override { return safe_.load(std::memory_order_acquire); }

  [[nodiscard]] int safe_calls() const noexcept { return safe_calls_.load(std::memory_order_relaxed); }
  [[nodiscard]] int writes() const noexcept { return writes_.load(std::memory_order_relaxed); }
  [[nodiscard]] int ignored_writes() const noexcept { return ignored_writes_.load(std::memory_order_relaxed); }
  [[nodiscard]] const hal::ActuatorCommand& last() const noexcept { return last_; }

 private:
  std::atomic<bool> safe_{false};
  std::atomic<int> safe_calls_{0};
  std::atomic<int> writes_{0};
  std::atomic<int> ignored_writes_{0};
  hal::ActuatorCommand last_{};
};

/// Wall time is the virtual clock; CPU time runs at half its rate (a task that was preempted for
/// half of its wall time). Proves which reading the executive judges budgets by.
class HalfRateCpuStopwatch final : public hal::Stopwatch {
 public:
  explicit HalfRateCpuStopwatch(const hal::VirtualClock& clock) noexcept : clock_(clock) {}
  [[nodiscard]] Nanos wall_now() const noexcept override { return clock_.now(); }
  [[nodiscard]] Nanos cpu_now() const noexcept override { return clock_.now() / 2; }

 private:
  const hal::VirtualClock& clock_;
};

/// A task that costs a scripted amount of virtual time per activation and records the context
/// it was handed. Cost precedence: per-activation function, then per-frame table, then default.
class ScriptedTask final : public Task {
 public:
  ScriptedTask(hal::VirtualClock& clock, std::string label, Nanos cost) noexcept
      : clock_(clock), label_(std::move(label)), cost_(cost) {}

  ScriptedTask& cost_in_frame(std::uint64_t frame, Nanos cost) {
    by_frame_[frame] = cost;
    return *this;
  }
  ScriptedTask& cost_by_activation(std::function<Nanos(std::size_t activation)> f) {
    by_activation_ = std::move(f);
    return *this;
  }
  /// Called at the start of every activation, before the cost is injected.
  ScriptedTask& on_run(std::function<void(const TaskContext&)> f) {
    hook_ = std::move(f);
    return *this;
  }
  /// The modelled cost this task reports per activation (judged when judge_on_model is set).
  ScriptedTask& model_by_activation(std::function<Nanos(std::size_t activation)> f) {
    model_by_activation_ = std::move(f);
    return *this;
  }
  /// Whether the task reports itself overloaded (Task::overloaded) after each activation.
  ScriptedTask& overloaded_by_activation(std::function<bool(std::size_t activation)> f) {
    overloaded_by_activation_ = std::move(f);
    return *this;
  }
  /// Appends "label@frame" to a shared trace at every activation.
  ScriptedTask& trace_into(std::vector<std::string>* trace) {
    trace_ = trace;
    return *this;
  }

  void run(const TaskContext& ctx) noexcept override {
    const std::size_t n = seen_.size();
    seen_.push_back(ctx);
    if (trace_ != nullptr) trace_->push_back(label_ + "@" + std::to_string(ctx.frame));
    if (hook_) hook_(ctx);
    Nanos cost = cost_;
    if (by_activation_) {
      cost = by_activation_(n);
    } else if (const auto it = by_frame_.find(ctx.frame); it != by_frame_.end()) {
      cost = it->second;
    }
    clock_.advance(cost);
    model_ = model_by_activation_ ? model_by_activation_(n) : Nanos{0};
    overloaded_ = overloaded_by_activation_ && overloaded_by_activation_(n);
  }
  [[nodiscard]] Nanos modelled_cost() const noexcept override { return model_; }
  [[nodiscard]] bool overloaded() const noexcept override { return overloaded_; }

  [[nodiscard]] const std::vector<TaskContext>& activations() const noexcept { return seen_; }
  [[nodiscard]] std::vector<std::uint64_t> frames() const {
    std::vector<std::uint64_t> f;
    f.reserve(seen_.size());
    for (const auto& c : seen_) f.push_back(c.frame);
    return f;
  }
  [[nodiscard]] const std::string& label() const noexcept { return label_; }

 private:
  hal::VirtualClock& clock_;
  std::string label_;
  Nanos cost_;
  std::map<std::uint64_t, Nanos> by_frame_;
  std::function<Nanos(std::size_t)> by_activation_;
  std::function<Nanos(std::size_t)> model_by_activation_;
  Nanos model_{0};
  std::function<bool(std::size_t)> overloaded_by_activation_;
  bool overloaded_ = false;
  std::function<void(const TaskContext&)> hook_;
  std::vector<std::string>* trace_ = nullptr;
  std::vector<TaskContext> seen_;
};

inline TaskSpec spec(std::string name, int every, int phase, Nanos budget, OverrunPolicy policy = OverrunPolicy::kWarn) {
  TaskSpec s;
  s.name = std::move(name);
  s.every = every;
  s.phase = phase;
  s.budget = budget;
  s.policy = policy;
  return s;
}

/// A deliberately odd start time, so that anything computed from 0 instead of the start shows.
inline constexpr Nanos kStart{1'000'000'007};

/// The executive's default base period (ExecutiveConfig), which the rigs run at.
inline constexpr Nanos kPeriod = 10ms;

/// When frame `frame` is due on the grid that starts at kStart.
inline Nanos due(std::uint64_t frame) { return kStart + static_cast<std::int64_t>(frame) * kPeriod; }

/// The frames in [0, end) in which a task with this `every` and `phase` is active.
inline std::vector<std::uint64_t> frames_where(std::uint64_t end, int every, int phase) {
  std::vector<std::uint64_t> out;
  for (std::uint64_t f = 0; f < end; ++f) {
    if (f % static_cast<std::uint64_t>(every) == static_cast<std::uint64_t>(phase)) out.push_back(f);
  }
  return out;
}

/// Wires ScriptedTasks, a VirtualClock (clock and stopwatch), a FakeActuators and an EventLog
/// into an Executive.
struct Rig {
  hal::VirtualClock clock{kStart};
  FakeActuators actuators;
  EventLog events;
  std::vector<TaskSpec> specs;
  std::vector<std::unique_ptr<ScriptedTask>> tasks;
  std::unique_ptr<Executive> exec;

  ScriptedTask& add(TaskSpec s, Nanos cost) {
    tasks.push_back(std::make_unique<ScriptedTask>(clock, s.name, cost));
    specs.push_back(std::move(s));
    return *tasks.back();
  }

  Executive& build(const ExecutiveConfig& config = {}, const hal::Stopwatch* stopwatch = nullptr) {
    std::vector<TaskBinding> bindings;
    for (std::size_t i = 0; i < specs.size(); ++i) bindings.push_back(TaskBinding{specs[i], tasks[i].get()});
    exec = std::make_unique<Executive>(config, std::move(bindings), clock, stopwatch ? *stopwatch : clock, actuators,
                                       &events);
    return *exec;
  }

  std::vector<Event> drain() {
    std::vector<Event> out;
    Event e;
    while (events.pop(e)) out.push_back(e);
    return out;
  }
};

inline std::vector<Event> of_kind(const std::vector<Event>& events, EventKind kind) {
  std::vector<Event> out;
  for (const auto& e : events) {
    if (e.kind == kind) out.push_back(e);
  }
  return out;
}

}  // namespace ringlet::executive::test
