#pragma once
// A thread that rebuilds a KnnRegressor's waiting index off the cycle (rebuild() allocates and
// takes O(n log n)). The cycle asks with request() and never waits for it except through
// wait_idle(), which only a lockstep run calls (its time is virtual), to make the new index
// appear at a defined frame whatever the host's speed.
#include <atomic>
#include <cstdint>
#include <thread>

#include "ringlet/planning/knn_regressor.hpp"

namespace ringlet::planning {

class RebuildWorker {
 public:
  /// Starts the thread (start-up). `knn` must outlive the worker.
  explicit RebuildWorker(KnnRegressor& knn);
  ~RebuildWorker();
  RebuildWorker(const RebuildWorker&) = delete;
  RebuildWorker& operator=(const RebuildWorker&) = delete;

  /// Asks for a rebuild over the first `count` stored experiences. The last index must have been
  /// published (KnnRegressor::rebuild refuses otherwise). No allocation, no lock.
  void request(std::size_t count) noexcept;
  /// Whether every requested rebuild has finished.
  [[nodiscard]] bool idle() const noexcept { return done_.load(std::memory_order_acquire) == requested_.load(std::memory_order_acquire); }
  /// Blocks until idle().
  void wait_idle() const noexcept;

 private:
  void loop();

  KnnRegressor& knn_;
  std::atomic<std::size_t> count_{0};
  std::atomic<std::uint64_t> requested_{0};
  std::atomic<std::uint64_t> done_{0};
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace ringlet::planning
