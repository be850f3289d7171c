#include "ringlet/planning/rebuild_worker.hpp"

namespace ringlet::planning {

RebuildWorker::RebuildWorker(KnnRegressor& knn) : knn_(knn), thread_([this] { loop(); }) {}

RebuildWorker::~RebuildWorker() {
  stop_.store(true, std::memory_order_release);
  requested_.fetch_add(1, std::memory_order_acq_rel);  // wakes the thread
  requested_.notify_one();
  thread_.join();
}

void RebuildWorker::request(std::size_t count) noexcept {
  count_.store(count, std::memory_order_release);
  requested_.fetch_add(1, std::memory_order_acq_rel);
  requested_.notify_one();
}

void RebuildWorker::wait_idle() const noexcept {
  for (;;) {
    const std::uint64_t done = done_.load(std::memory_order_acquire);
    if (done == requested_.load(std::memory_order_acquire)) return;
    done_.wait(done, std::memory_order_acquire);
  }
}

void RebuildWorker::loop() {
  std::uint64_t seen = 0;
  for (;;) {
    requested_.wait(seen, std::memory_order_acquire);
    if (stop_.load(std::memory_order_acquire)) return;
    seen = requested_.load(std::memory_order_acquire);
    (void)knn_.rebuild(count_.load(std::memory_order_acquire));
    done_.store(seen, std::memory_order_release);
    done_.notify_all();
  }
}

}  // namespace ringlet::planning
