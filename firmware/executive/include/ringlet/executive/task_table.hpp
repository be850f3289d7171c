#pragma once
// The task table: the one place that says what runs, how often, in which frame, in which order
// and with what budget (cf. ArduPilot's scheduler table, F Prime's rate groups).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ringlet/hal/time.hpp"

namespace ringlet::executive {

using hal::Nanos;

/// What the executive does when a task exceeds its budget. Every policy counts the overrun and
/// emits a rate-limited warning; the others do more.
enum class OverrunPolicy : std::uint8_t {
  kWarn,      // count and warn only
  kSkip,      // also skip the task's next activation
  kDegrade,   // also raise the task's degrade level (it is told to do less)
  kFailsafe,  // also command the HAL safe state
};

[[nodiscard]] std::string_view to_string(OverrunPolicy p) noexcept;
/// Parses "warn", "skip", "degrade", "failsafe"; returns false for anything else.
[[nodiscard]] bool parse_policy(std::string_view text, OverrunPolicy& out) noexcept;

struct TaskSpec {
  std::string name;
  int every = 1;   // runs in frames where frame % every == phase: rate = base rate / every
  int phase = 0;   // 0 <= phase < every
  Nanos budget{0};  // per activation, 0 < budget <= period
  OverrunPolicy policy = OverrunPolicy::kWarn;
  // Order: a task's position in the table is its order inside a frame.

  [[nodiscard]] bool active_in(std::uint64_t frame) const noexcept {
    return frame % static_cast<std::uint64_t>(every) == static_cast<std::uint64_t>(phase);
  }
};

struct ExecutiveConfig {
  Nanos period{10'000'000};        // base period: 10 ms (100 Hz, the NAO DCM period) by default
  int watchdog_periods = 5;        // safe state when no frame starts for this many periods; 0: off
  int warn_every_frames = 100;     // at most one overrun warning per task per this many frames
  int degrade_max_level = 3;
  int degrade_recover_after = 20;  // on-budget activations before the degrade level drops by one
  bool overrun_on_cpu_time = false;  // measure budgets on thread CPU time instead of wall time
  // Lockstep: the overrun policies act on each task's modelled cost (Task::modelled_cost(), a pure
  // function of the work it did), so that a simulated run is the same whatever the host's load.
  // The measured time is still recorded and its overruns counted beside (TaskStats::measured_overruns).
  bool judge_on_model = false;
};

/// Longest hyperperiod (in frames) the overload check will walk; beyond it the table is refused.
inline constexpr std::uint64_t kMaxHyperperiod = 100'000;
/// Most rows a table may have: a controller has a handful of tasks, and the overload check walks
/// rows × hyperperiod, which must stay quick however the table was written.
inline constexpr std::size_t kMaxTasks = 64;
/// Most problems validate() spells out; the rest are counted in one last "... and K more" line,
/// so a table overloaded in all of its 100,000 frames gives 21 lines, not 100,001.
inline constexpr std::size_t kMaxProblemsListed = 20;

/// The problems with a table, one message each; empty means valid. Checks: period > 0; at most
/// kMaxTasks rows; names non-empty and unique; every >= 1; 0 <= phase < every;
/// 0 < budget <= period; and, over the hyperperiod, no frame whose active budgets add up to more
/// than the period. At most kMaxProblemsListed messages, then "... and K more problems".
[[nodiscard]] std::vector<std::string> validate(const ExecutiveConfig& config, std::span<const TaskSpec> tasks);

/// `problems` as "\n  - problem" lines, at most `max_listed` of them followed by "... and K more"
/// when there are more: every list of problems shown to a person goes through this.
[[nodiscard]] std::string list_problems(std::span<const std::string> problems,
                                        std::size_t max_listed = kMaxProblemsListed);

}  // namespace ringlet::executive
