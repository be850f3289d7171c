#pragma once
// The fixed-rate cyclic executive. Frame k is due at start + k * period; the executive sleeps to
// that absolute instant on its clock, then runs the tasks active in frame k in table order, each
// measured (wall + thread CPU time) against its budget. A frame that ends late never triggers a
// burst: the executive skips to the next frame still in the future, keeping the phase, and counts
// the frames it lost as slips. Nothing here allocates once run() has started.
#include <atomic>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "ringlet/executive/event_log.hpp"
#include "ringlet/executive/stats.hpp"
#include "ringlet/executive/task.hpp"
#include "ringlet/executive/task_table.hpp"
#include "ringlet/hal/clock.hpp"
#include "ringlet/hal/robot.hpp"

namespace ringlet::executive {

struct TaskBinding {
  TaskSpec spec;
  Task* task = nullptr;
};

class TableError : public std::runtime_error {
 public:
  explicit TableError(std::vector<std::string> problems);
  [[nodiscard]] const std::vector<std::string>& problems() const noexcept { return problems_; }

 private:
  std::vector<std::string> problems_;
};

/// Watches the run from outside the task table (scoring against ground truth, recording): called
/// after every executed frame, never judged against a budget. It must not change what the
/// controller does.
class FrameObserver {
 public:
  virtual ~FrameObserver() = default;
  virtual void frame_done(std::uint64_t frame, Nanos frame_start) noexcept = 0;
};

/// Why run() returned.
enum class StopReason : std::uint8_t { kFrameLimit, kRequested };

class Executive {
 public:
  /// Validates the table (throws TableError listing every problem). `safe_target` receives
  /// enter_safe_state() under the failsafe policy; `events` (optional) receives overrun events.
  Executive(const ExecutiveConfig& config, std::vector<TaskBinding> tasks, hal::Clock& clock,
            const hal::Stopwatch& stopwatch, hal::Actuators& safe_target, EventLog* events = nullptr);

  /// Runs frames until `max_frames` frame numbers have passed (executed or slipped; 0: no limit)
  /// or a stop is requested. May be called again to continue.
  StopReason run(std::uint64_t max_frames = 0) noexcept;

  /// Thread-safe and async-signal-safe: the run ends after the current frame.
  void request_stop() noexcept { stop_.store(true, std::memory_order_relaxed); }
  [[nodiscard]] std::atomic<bool>& stop_flag() noexcept { return stop_; }

  /// Incremented at the start of every frame; the watchdog watches it.
  [[nodiscard]] const std::atomic<std::uint64_t>& heartbeat() const noexcept { return heartbeat_; }

  /// Start-up only: `observer` (or null) sees every frame from now on.
  void set_observer(FrameObserver* observer) noexcept { observer_ = observer; }

  [[nodiscard]] const ExecutiveConfig& config() const noexcept { return config_; }
  [[nodiscard]] std::span<const TaskBinding> tasks() const noexcept { return tasks_; }
  [[nodiscard]] std::span<const TaskStats> task_stats() const noexcept { return stats_; }
  [[nodiscard]] const FrameStats& frame_stats() const noexcept { return frame_stats_; }
  [[nodiscard]] std::uint64_t next_frame() const noexcept { return next_frame_; }
  [[nodiscard]] bool failsafe_triggered() const noexcept { return failsafe_triggered_; }
  /// Index of the task whose overrun triggered the failsafe, or -1.
  [[nodiscard]] int failsafe_task() const noexcept { return failsafe_task_; }

 private:
  void run_frame(std::uint64_t frame, Nanos frame_start) noexcept;
  void run_task(std::size_t index, std::uint64_t frame, Nanos frame_start) noexcept;
  void on_overrun(std::size_t index, std::uint64_t frame, Nanos measured) noexcept;
  void on_overload(std::size_t index) noexcept;
  void on_budget_met(std::size_t index) noexcept;
  void count_slipped_activations(std::uint64_t first, std::uint64_t end) noexcept;
  void emit(const Event& e) noexcept;

  ExecutiveConfig config_;
  std::vector<TaskBinding> tasks_;
  std::vector<TaskStats> stats_;
  FrameStats frame_stats_{};
  hal::Clock& clock_;
  const hal::Stopwatch& stopwatch_;
  hal::Actuators& safe_target_;
  EventLog* events_;
  FrameObserver* observer_ = nullptr;

  bool started_ = false;
  Nanos start_{0};
  std::uint64_t next_frame_ = 0;
  std::uint64_t last_frame_overrun_warn_ = 0;
  bool failsafe_triggered_ = false;
  int failsafe_task_ = -1;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> heartbeat_{0};
};

}  // namespace ringlet::executive
