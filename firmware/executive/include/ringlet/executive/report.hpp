#pragma once
// The executive's timing report: a table for the terminal and the same figures as JSON.
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "ringlet/executive/event_log.hpp"
#include "ringlet/executive/executive.hpp"

namespace ringlet::executive {

/// Per task: rate, budget, policy, runs, wall MIN/AVG/P50/P99/MAX, CPU P99, OVR, SKIP, share of
/// the frame; then the frame line (frames, overruns, slips, busy p99, wake latency p99).
void print_timing_table(std::ostream& out, const Executive& exec);

/// The same data (and p99.9, CPU min/avg/max) as JSON; durations in microseconds.
[[nodiscard]] nlohmann::json timing_json(const Executive& exec);

/// A histogram's min, mean, p50, p99, p99.9 and max in microseconds (the keys timing_json uses).
[[nodiscard]] nlohmann::json histogram_json(const DurationHistogram& h);

/// One line describing an event, for the non-real-time log drain.
[[nodiscard]] std::string describe(const Event& event, const Executive& exec);

}  // namespace ringlet::executive
