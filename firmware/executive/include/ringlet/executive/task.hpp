#pragma once
// What the executive hands a task each activation, and the interface a task implements.
#include <atomic>
#include <cstdint>

#include "ringlet/hal/clock.hpp"

namespace ringlet::executive {

using hal::Nanos;

/// One activation's view of time. `now` and `deadline` are on the executive's schedule clock
/// (virtual in lockstep simulation); `out_of_time()` asks the measuring stopwatch, so budgeted
/// work can stop in time and resume at its next activation.
struct TaskContext {
  std::uint64_t frame = 0;  // frame number since start; frames lost to a slip are counted too
  Nanos frame_start{0};     // when this frame was due
  Nanos now{0};             // when this activation started
  Nanos deadline{0};        // min(now + budget, frame_start + period)
  Nanos period{0};          // the base period
  int degrade_level = 0;    // 0: full work; >0: do less (raised by the degrade overrun policy)

  const hal::Stopwatch* stopwatch = nullptr;
  Nanos started_wall{0};  // stopwatch reading when the activation started
  Nanos budget{0};        // deadline - now, on the stopwatch
  std::atomic<bool>* stop_flag = nullptr;

  [[nodiscard]] Nanos time_left() const noexcept { return budget - (stopwatch->wall_now() - started_wall); }
  [[nodiscard]] bool out_of_time() const noexcept { return time_left() <= Nanos{0}; }
  /// True in the first frame of every `span` of base periods (frame 0, then every span / period
  /// frames): what a task posts "once a second" posts in these frames. False if span < period.
  [[nodiscard]] bool first_frame_of_each(Nanos span) const noexcept {
    const auto frames = period.count() > 0 ? static_cast<std::uint64_t>(span / period) : 0U;
    return frames > 0 && frame % frames == 0;
  }
  /// Ends the run after this frame (e.g. the mission is complete).
  void request_stop() const noexcept { stop_flag->store(true, std::memory_order_relaxed); }
};

class Task {
 public:
  virtual ~Task() = default;
  virtual void run(const TaskContext& ctx) noexcept = 0;

  /// What the activation that just ran costs on the target board, computed from the work the
  /// task counted (pixels classified, RANSAC trials, ringlets) and never from a clock. In
  /// lockstep the overrun policies act on this figure (ExecutiveConfig::judge_on_model), so that
  /// what the controller does is a pure function of seed and configuration. A task whose work
  /// does not vary returns its nominal cost; the default, zero, is for tasks that are never judged
  /// on a model (tests on scripted clocks).
  [[nodiscard]] virtual Nanos modelled_cost() const noexcept { return Nanos{0}; }

  /// True when the activation that just ran kept its budget only by cutting work it needs, not
  /// work it may give up (a vision frame whose line search the deadline stopped, against one that
  /// left out optional classifications). Not an overrun, but the degrade policy acts on it as on
  /// one: the task is overloaded at its level, and the next activations should do less.
  [[nodiscard]] virtual bool overloaded() const noexcept { return false; }
};

}  // namespace ringlet::executive
