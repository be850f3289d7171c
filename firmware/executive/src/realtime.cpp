#include "ringlet/executive/realtime.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace ringlet::executive {

std::vector<std::string> apply_realtime_settings(const RealtimeSettings& settings) {
  std::vector<std::string> warnings;
  if (settings.fifo_priority != 0) {
    const int lo = sched_get_priority_min(SCHED_FIFO);
    const int hi = sched_get_priority_max(SCHED_FIFO);
    if (settings.fifo_priority < lo || settings.fifo_priority > hi) {
      warnings.push_back("realtime priority " + std::to_string(settings.fifo_priority) + " is outside " +
                         std::to_string(lo) + ".." + std::to_string(hi) + "; running with the normal scheduler");
    } else {
      sched_param param{};
      param.sched_priority = settings.fifo_priority;
      if (const int rc = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param); rc != 0) {
        warnings.push_back(std::string("SCHED_FIFO priority not granted (") + std::strerror(rc) +
                           "); running with the normal scheduler: expect more jitter");
      }
    }
  }
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
