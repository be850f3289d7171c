#include "ringlet/executive/watchdog.hpp"

#include <pthread.h>

#include <cstdio>

namespace ringlet::executive {

bool WatchdogMonitor::observe(std::uint64_t heartbeat, Nanos now) noexcept {
  if (!seen_ || heartbeat != last_beat_) {
    seen_ = true;
    last_beat_ = heartbeat;
    last_change_ = now;
    stalled_for_ = Nanos{0};
    return false;
  }
  stalled_for_ = now - last_change_;
  if (!tripped_ && stalled_for_ > timeout_) {
    tripped_ = true;
    return true;
  }
  return false;
}

WatchdogThread::WatchdogThread(hal::Clock& clock, const std::atomic<std::uint64_t>& heartbeat,
                               hal::Actuators& actuators, Nanos timeout, Nanos poll,
                               const std::atomic<bool>* shutdown)
    : clock_(clock), heartbeat_(heartbeat), actuators_(actuators), monitor_(timeout), poll_(poll), shutdown_(shutdown) {
  thread_ = std::thread([this] { loop(); });
}

WatchdogThread::~WatchdogThread() { stop(); }

void WatchdogThread::stop() noexcept {
  running_.store(false, std::memory_order_release);
  if (thread_.joinable()) thread_.join();
}

void WatchdogThread::loop() noexcept {
  // A name the kernel shows (/proc/PID/task/TID/comm, top -H), so its priority can be checked.
  (void)pthread_setname_np(pthread_self(), "rl-watchdog");
  while (running_.load(std::memory_order_acquire)) {
    const Nanos now = clock_.now();
    if (shutdown_ != nullptr && shutdown_->load(std::memory_order_acquire) && !shutdown_seen_.load()) {
      // SIGINT/SIGTERM: stop the motors now, even if the cycle is stuck and never sees the flag.
      actuators_.enter_safe_state();
      shutdown_seen_.store(true, std::memory_order_release);
    }
    if (monitor_.observe(heartbeat_.load(std::memory_order_acquire), now)) {
      actuators_.enter_safe_state();
      stalled_ns_.store(monitor_.stalled_for().count(), std::memory_order_release);
      fired_.store(true, std::memory_order_release);
      std::fprintf(stderr, "ringlet: WATCHDOG: no frame started for %.1f ms; safe state commanded\n",
                   static_cast<double>(monitor_.stalled_for().count()) / 1e6);
    }
    clock_.sleep_until(now + poll_);
  }
}

}  // namespace ringlet::executive
