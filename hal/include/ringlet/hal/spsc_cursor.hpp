#pragma once
// The indices of a bounded single-producer single-consumer queue whose slots the user owns (a
// std::vector allocated at start-up): the producer fills slot `write_slot()` and publishes it, the
// consumer processes slot `read_slot()` and releases it. Used by the recorders (hal/replay's
// RecordingRobot, the whiteboard's MessageLogger) to hand records from the cycle thread to a
// writer thread without locking or allocating on the cycle path.
//
// Producer side: can_write / write_slot / publish never block; wait_writable blocks (for the
// lossless recording modes, where the producer is allowed to wait). Consumer side: can_read /
// read_slot / release; release wakes a producer blocked in wait_writable.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <stdexcept>

namespace ringlet::hal {

class SpscCursor {
 public:
  explicit SpscCursor(std::size_t capacity) : capacity_(capacity) {
    if (capacity == 0) throw std::invalid_argument("SpscCursor: capacity must be at least 1");
  }
  SpscCursor(const SpscCursor&) = delete;
  SpscCursor& operator=(const SpscCursor&) = delete;

  [[nodiscard]] std::size_t capacity() const noexcept { return capacity_; }

  // ---- producer -----------------------------------------------------------------------------
  [[nodiscard]] bool can_write() const noexcept {
    return head_.load(std::memory_order_relaxed) - tail_.load(std::memory_order_acquire) < capacity_;
  }
  [[nodiscard]] std::size_t write_slot() const noexcept {
    return static_cast<std::size_t>(head_.load(std::memory_order_relaxed) % capacity_);
  }
  void publish() noexcept { head_.store(head_.load(std::memory_order_relaxed) + 1, std::memory_order_release); }
  /// Blocks until a slot is free (the consumer releases one).
  void wait_writable() const noexcept {
    for (;;) {
      const std::uint64_t tail = tail_.load(std::memory_order_acquire);
      if (head_.load(std::memory_order_relaxed) - tail < capacity_) return;
      tail_.wait(tail, std::memory_order_acquire);
    }
  }

  // ---- consumer -----------------------------------------------------------------------------
  [[nodiscard]] bool can_read() const noexcept {
    return head_.load(std::memory_order_acquire) != tail_.load(std::memory_order_relaxed);
  }
  [[nodiscard]] std::size_t read_slot() const noexcept {
    return static_cast<std::size_t>(tail_.load(std::memory_order_relaxed) % capacity_);
  }
  void release() noexcept {
    tail_.store(tail_.load(std::memory_order_relaxed) + 1, std::memory_order_release);
    tail_.notify_all();
  }

 private:
  std::size_t capacity_;
  std::atomic<std::uint64_t> head_{0};  // slots published (written by the producer only)
  std::atomic<std::uint64_t> tail_{0};  // slots released (written by the consumer only)
};

}  // namespace ringlet::hal
