#pragma once
// A fixed single-producer / single-consumer ring: the cycle thread pushes, one non-real-time
// thread pops. Neither side blocks or allocates; when the ring is full the item is dropped and
// counted, never waited for. The way anything leaves the cycle for I/O.
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

namespace ringlet::executive {

template <class T, std::size_t Capacity>
class SpscQueue {
 public:
  static constexpr std::size_t kCapacity = Capacity;

  /// Producer side only.
  bool push(const T& item) noexcept {
    const auto head = head_.load(std::memory_order_relaxed);
    if (head - tail_.load(std::memory_order_acquire) >= Capacity) {
      dropped_.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    ring_[head % Capacity] = item;
    head_.store(head + 1, std::memory_order_release);
    return true;
  }
  /// Consumer side only. False when empty.
  bool pop(T& out) noexcept {
    const auto tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_.load(std::memory_order_acquire)) return false;
    out = ring_[tail % Capacity];
    tail_.store(tail + 1, std::memory_order_release);
    return true;
  }
  [[nodiscard]] std::uint64_t dropped() const noexcept { return dropped_.load(std::memory_order_relaxed); }

 private:
  std::array<T, Capacity> ring_{};
  std::atomic<std::uint64_t> head_{0};  // next write
  std::atomic<std::uint64_t> tail_{0};  // next read
  std::atomic<std::uint64_t> dropped_{0};
};

}  // namespace ringlet::executive
