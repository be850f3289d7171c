#pragma once
// Optional real-time settings for the executive's thread: SCHED_FIFO priority, locked memory
// (no page faults in the cycle) and CPU affinity. Where the process is not allowed (no
// CAP_SYS_NICE, RLIMIT_MEMLOCK, a container), each setting that fails yields a warning, not a
// failure: a desktop simulation must still run.
#include <pthread.h>

#include <string>
#include <string_view>
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

/// SCHED_FIFO at `priority` for `thread` (`who` names it in the warning); returns a warning when
/// the priority is out of range or not granted, the thread's scheduler then left as it was.
[[nodiscard]] std::vector<std::string> set_fifo_priority(pthread_t thread, int priority, std::string_view who);

/// The watchdog's SCHED_FIFO priority for a cycle at `cycle_priority` (0: none, the watchdog keeps
/// the normal scheduler too). One above the cycle's, so that a cycle spinning at its priority
/// cannot starve the thread that must stop the motors: on a shared CPU the watchdog preempts it,
/// and the kernel's real-time throttling is not what lets it run. At the top priority both share
/// it; different CPUs keep them apart then.
[[nodiscard]] int watchdog_priority(int cycle_priority) noexcept;

}  // namespace ringlet::executive
