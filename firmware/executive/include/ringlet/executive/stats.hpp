#pragma once
// Statistics the executive keeps per task and per frame. Fixed size, updated in place.
#include <cstdint>

#include "ringlet/executive/histogram.hpp"

namespace ringlet::executive {

struct TaskStats {
  std::uint64_t runs = 0;
  std::uint64_t overruns = 0;          // activations over budget, as judged (the policy acted on these)
  std::uint64_t measured_overruns = 0; // activations whose measured time was over budget (wall or CPU)
  std::uint64_t skipped = 0;           // activations not run: skip policy or frames lost to a slip
  std::uint64_t degraded_runs = 0;     // activations that ran with degrade_level > 0
  std::uint64_t overloads = 0;         // activations in budget only by cutting needed work (Task::overloaded)
  int degrade_level = 0;
  int clean_streak = 0;                // on-budget activations since the last overrun
  bool skip_next = false;
  std::uint64_t last_warn_frame = 0;
  std::uint64_t warned = 0;
  std::uint64_t suppressed_warnings = 0;
  DurationHistogram wall;              // wall time per activation
  DurationHistogram cpu;               // thread CPU time per activation
  DurationHistogram model;             // modelled cost per activation (Task::modelled_cost())
};

struct FrameStats {
  std::uint64_t frames = 0;            // frames executed
  std::uint64_t frame_overruns = 0;    // frames whose tasks ended after the next frame was due
  std::uint64_t slips = 0;             // frames skipped to keep the phase after an overrun
  DurationHistogram busy;              // time from frame start to the end of its last task
  DurationHistogram wake_latency;      // how late the executive woke for each frame
};

}  // namespace ringlet::executive
