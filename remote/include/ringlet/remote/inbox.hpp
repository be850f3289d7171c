#pragma once
// Remote writes on their way to the whiteboard. The bridge (its own thread, or the lockstep
// observer) pushes the requests it accepted; the cycle delivers them at one defined point
// (deliver(): the firmware's whiteboard task, before dispatch), so that a run in which nothing
// remote writes stays exactly what it was, and one that is written to sees each request at a
// frame boundary, whole. One bounded single-producer single-consumer queue per accepted type,
// allocated at start-up: neither side blocks, locks or allocates; a full queue drops the request
// and counts it.
#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <vector>

#include "ringlet/hal/spsc_cursor.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::remote {

class Inbox {
 public:
  /// `accepted[i]`: type wb::kTypes[i] may be written remotely; each such type gets `capacity`
  /// slots.
  Inbox(const std::array<bool, wb::kTypeCount>& accepted, std::size_t capacity)
      : Inbox(accepted, capacity, wb::AllMessages{}) {}
  Inbox(const Inbox&) = delete;
  Inbox& operator=(const Inbox&) = delete;

  /// Producer side. False (and counted) when T is not accepted or its queue is full.
  template <wb::Message T>
  bool push(const T& msg) noexcept {
    Queue<T>& q = std::get<Queue<T>>(queues_);
    if (q.slots.empty() || !q.cursor.can_write()) {
      dropped_.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    q.slots[q.cursor.write_slot()] = msg;
    q.cursor.publish();
    return true;
  }

  /// Consumer side (the cycle): posts every waiting request, types in id order, each type's
  /// oldest first. Returns how many were posted.
  std::size_t deliver(wb::Whiteboard& board) noexcept {
    std::size_t n = 0;
    std::apply([&](auto&... q) { ((n += deliver_one(q, board)), ...); }, queues_);
    return n;
  }

  [[nodiscard]] std::uint64_t dropped() const noexcept { return dropped_.load(std::memory_order_relaxed); }

 private:
  struct QueueSpec {
    bool on;
    std::size_t capacity;
  };
  template <class T>
  struct Queue {
    Queue(QueueSpec spec)  // NOLINT(google-explicit-constructor): built in place by the tuple
        : cursor(std::max<std::size_t>(spec.capacity, 1)), slots(spec.on ? std::max<std::size_t>(spec.capacity, 1) : 0) {}
    hal::SpscCursor cursor;
    std::vector<T> slots;  // empty: T is not accepted
  };
  template <class T>
  static std::size_t deliver_one(Queue<T>& q, wb::Whiteboard& board) noexcept {
    std::size_t n = 0;
    while (!q.slots.empty() && q.cursor.can_read()) {
      board.post(q.slots[q.cursor.read_slot()]);
      q.cursor.release();
      ++n;
    }
    return n;
  }
  template <class... Ts>
  Inbox(const std::array<bool, wb::kTypeCount>& accepted, std::size_t capacity, wb::TypeList<Ts...>)
      : queues_(QueueSpec{accepted[wb::kIndexOf<Ts>], capacity}...) {}
  template <class L>
  struct Queues;
  template <class... Ts>
  struct Queues<wb::TypeList<Ts...>> {
    using type = std::tuple<Queue<Ts>...>;
  };

  typename Queues<wb::AllMessages>::type queues_;
  std::atomic<std::uint64_t> dropped_{0};
};

}  // namespace ringlet::remote
