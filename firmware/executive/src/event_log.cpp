#include "ringlet/executive/event_log.hpp"

namespace ringlet::executive {

bool EventLog::push(const Event& e) noexcept {
  const auto head = head_.load(std::memory_order_relaxed);
  if (head - tail_.load(std::memory_order_acquire) >= kCapacity) {
    dropped_.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  ring_[head % kCapacity] = e;
  head_.store(head + 1, std::memory_order_release);
  return true;
}

bool EventLog::pop(Event& out) noexcept {
  const auto tail = tail_.load(std::memory_order_relaxed);
  if (tail == head_.load(std::memory_order_acquire)) return false;
  out = ring_[tail % kCapacity];
  tail_.store(tail + 1, std::memory_order_release);
  return true;
}

}  // namespace ringlet::executive
