#include "ringlet/executive/realtime.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace ringlet::executive {

std::vector<std::string> set_fifo_priority(pthread_t thread, int priority, std::string_view who) {
  std::vector<std::string> warnings;
  const int lo = sched_get_priority_min(SCHED_FIFO);
  const int hi = sched_get_priority_max(SCHED_FIFO);
  if (priority < lo || priority > hi) {
    warnings.push_back("realtime priority " + std::to_string(priority) + " for the " + std::string(who) +
                       " is outside " + std::to_string(lo) + ".." + std::to_string(hi) +
                       "; running with the normal scheduler");
    return warnings;
  }
  sched_param param{};
  param.sched_priority = priority;
  if (const int rc = pthread_setschedparam(thread, SCHED_FIFO, &param); rc != 0) {
    warnings.push_back("SCHED_FIFO priority not granted to the " + std::string(who) + " (" + std::strerror(rc) +
                       "); running with the normal scheduler: expect more jitter");
  }
  return warnings;
}

int watchdog_priority(int cycle_priority) noexcept {
  if (cycle_priority <= 0) return 0;
  return std::min(cycle_priority + 1, sched_get_priority_max(SCHED_FIFO));
}

std::vector<std::string> apply_realtime_settings(const RealtimeSettings& settings) {
  std::vector<std::string> warnings;
  if (settings.fifo_priority != 0) warnings = set_fifo_priority(pthread_self(), settings.fifo_priority, "cycle");
  if (settings.lock_memory && mlockall(MCL_CURRENT | MCL_FUTURE) != 0) {
    warnings.push_back(std::string("mlockall failed (") + std::strerror(errno) +
                       "); memory may be paged: raise RLIMIT_MEMLOCK or run with CAP_IPC_LOCK");
  }
  if (settings.cpu >= 0) {
    const long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    if (settings.cpu >= cpus || settings.cpu >= CPU_SETSIZE) {
      warnings.push_back("cpu " + std::to_string(settings.cpu) + " does not exist (" + std::to_string(cpus) +
                         " online); affinity left unchanged");
    } else {
      cpu_set_t set;
      CPU_ZERO(&set);
      CPU_SET(static_cast<std::size_t>(settings.cpu), &set);
      if (const int rc = pthread_setaffinity_np(pthread_self(), sizeof(set), &set); rc != 0) {
        warnings.push_back(std::string("CPU affinity not set (") + std::strerror(rc) + ")");
      }
    }
  }
  return warnings;
}

}  // namespace ringlet::executive
