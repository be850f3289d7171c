#pragma once
// Optional real-time settings for the executive's thread: SCHED_FIFO priority, locked memory
// (no page faults in the cycle) and CPU affinity. Where the process is not allowed (no
// CAP_SYS_NICE, RLIMIT_MEMLOCK, a container), each setting that fails yields a warning, not a
// failure: a desktop simulation must still run.
#include <string>
#include <vector>

namespace ringlet::executive {

struct RealtimeSettings {
  int fifo_priority = 0;     // 1..99 requests SCHED_FIFO; 0 leaves the scheduler alone
  bool lock_memory = false;  // mlockall(MCL_CURRENT | MCL_FUTURE)
  int cpu = -1;              // pin the calling thread to this CPU; -1 leaves it
};

/// Applies the settings to the calling thread/process; returns one warning per setting that
/// could not be applied (empty when all took effect). Invalid values are warnings too.
[[nodiscard]] std::vector<std::string> apply_realtime_settings(const RealtimeSettings& settings);

}  // namespace ringlet::executive
