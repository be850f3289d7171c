#pragma once
// How much time the vision step has left: a stopwatch and an absolute deadline on it. No
// std::function, no allocation; a default Deadline never expires (and nothing is timed).
#include <limits>

#include "ringlet/hal/clock.hpp"
#include "ringlet/hal/time.hpp"

namespace ringlet::vision {

struct Deadline {
  const hal::Stopwatch* watch = nullptr;
  hal::Nanos end{std::numeric_limits<hal::Nanos::rep>::max()};
  bool cpu = false;  // judge on the thread's CPU time instead of wall time (as the executive can)
  // The modelled board time (cost_model.hpp's default model) the frame may take: in lockstep
  // simulation the executive judges the budget on that model, not on a clock, so the pipeline
  // counts its work against it where it can cut (the robot classifications, which run last).
  hal::Nanos model_budget{std::numeric_limits<hal::Nanos::rep>::max()};

  /// `budget` from now on `watch`.
  [[nodiscard]] static Deadline after(const hal::Stopwatch& w, hal::Nanos budget, bool use_cpu = false) noexcept {
    const hal::Nanos now = use_cpu ? w.cpu_now() : w.wall_now();
    return {&w, now + budget, use_cpu};
  }
  [[nodiscard]] hal::Nanos now() const noexcept {
    if (watch == nullptr) return hal::Nanos{0};
    return cpu ? watch->cpu_now() : watch->wall_now();
  }
  [[nodiscard]] bool expired() const noexcept { return watch != nullptr && now() >= end; }
  [[nodiscard]] hal::Nanos left() const noexcept {
    if (watch == nullptr) return hal::Nanos{std::numeric_limits<hal::Nanos::rep>::max()};
    return end - now();
  }
};

}  // namespace ringlet::vision
