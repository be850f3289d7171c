#pragma once
// Busy threads, one per core (at least two), for as long as the object lives: the loaded machine
// that a lockstep run must ignore and that a real-clock test must survive. Header-only so that
// any test can use it without linking anything.
#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace ringlet::test {

class CpuHog {
 public:
  // kShared: the busy threads compete for the cores on equal terms with everything else (a
  // lockstep run must not notice). kIdle: they run only when a core would otherwise idle
  // (SCHED_IDLE), as background work beside a controller that owns its CPU does on a robot: the
  // cores stay busy (caches, memory bandwidth), but the controller's threads are never kept
  // waiting for one.
  enum class Priority { kShared, kIdle };

  explicit CpuHog(Priority priority = Priority::kShared) {
    const unsigned n = std::max(2U, std::thread::hardware_concurrency());
    threads_.reserve(n);
    for (unsigned i = 0; i < n; ++i) {
      threads_.emplace_back([this, priority] {
        if (priority == Priority::kIdle) {
          const sched_param none{};
          pthread_setschedparam(pthread_self(), SCHED_IDLE, &none);  // lowering needs no privilege
        }
        std::uint64_t x = 1;
        while (!stop_.load(std::memory_order_relaxed)) x = x * 6364136223846793005ULL + 1;
        sink_.fetch_add(x, std::memory_order_relaxed);
      });
    }
  }
  ~CpuHog() {
    stop_.store(true, std::memory_order_relaxed);
    for (auto& t : threads_) t.join();
  }
  CpuHog(const CpuHog&) = delete;
  CpuHog& operator=(const CpuHog&) = delete;

 private:
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> sink_{0};
  std::vector<std::thread> threads_;
};

}  // namespace ringlet::test
