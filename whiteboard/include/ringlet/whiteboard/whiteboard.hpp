#pragma once
// The class-oriented whiteboard (after Mi-Pal's guWhiteboard): typed messages from schema.def,
// a ring of generations per type, and subscriptions.
//
// Threads: each type has ONE writer thread (any thread, but the same one for that type); any
// number of threads may get/read/has_new at once. post/get/read never lock, block or allocate.
// Subscriptions are made at start-up (before the first dispatch() and before
// start_tool_thread()); after that subscribe() throws std::logic_error.
//
// Dispatch rule: dispatch() (called by the executive at one fixed point of its cycle) runs the
// kCycle callbacks on the calling thread, types in id order, then subscriptions of a type in the
// order they were made; each subscription gets every generation posted since its last delivery,
// oldest first, or is told how many it missed if the ring no longer holds them. kToolThread
// callbacks get the same, on the whiteboard's own non-real-time thread, polled every few ms.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "ringlet/whiteboard/binary.hpp"
#include "ringlet/whiteboard/fixed_string.hpp"
#include "ringlet/whiteboard/messages.hpp"
#include "ringlet/whiteboard/result.hpp"
#include "ringlet/whiteboard/ring.hpp"

namespace ringlet::wb {

enum class Delivery : std::uint8_t {
  kCycle,       // by dispatch(), on the executive's thread, deterministic order
  kToolThread,  // on the whiteboard's tool thread (start_tool_thread), for tools and logging
};

struct SubscriptionId {
  std::uint32_t value = 0;
  friend bool operator==(SubscriptionId, SubscriptionId) = default;
};

/// What a two-argument callback learns besides the message.
struct DeliveryInfo {
  std::uint64_t generation = 0;  // the generation delivered
  std::uint64_t missed = 0;      // generations lost (overwritten) just before this one
};

class ToolThread;

class Whiteboard {
 public:
  /// generations: ring depth per type (rounded up to a power of two, at least 2). All ring memory
  /// is allocated here.
  explicit Whiteboard(std::size_t generations = 8);
  ~Whiteboard();
  Whiteboard(const Whiteboard&) = delete;
  Whiteboard& operator=(const Whiteboard&) = delete;

  [[nodiscard]] std::size_t depth() const noexcept { return depth_; }

  template <Message T>
  void post(const T& msg) noexcept {
    channel<T>().ring.post(msg);
  }
  /// The newest T, or T{} if none was ever posted.
  template <Message T>
  [[nodiscard]] T get() const noexcept {
    return channel<T>().ring.newest();
  }
  /// How many T were posted so far (= the newest generation; 0: none).
  template <Message T>
  [[nodiscard]] std::uint64_t generation() const noexcept {
    return channel<T>().ring.generation();
  }
  template <Message T>
  [[nodiscard]] bool has_new(std::uint64_t since) const noexcept {
    return generation<T>() > since;
  }
  /// Generation gen of T: kOk with the message, kMissed (with how many are lost) if the ring has
  /// moved past it, kNotYet if it was not posted yet.
  template <Message T>
  [[nodiscard]] ReadResult<T> read(std::uint64_t gen) const noexcept {
    return channel<T>().ring.read(gen);
  }
  /// Every generation of T after `seen`, oldest first, to `on_message(const T&)`; generations the
  /// ring no longer holds are counted to `on_missed(n)`. Sets `seen` to the newest generation: a
  /// reader that polls (a recording task) misses nothing the ring still holds, and allocates nothing.
  template <Message T, class OnMessage, class OnMissed>
  void read_since(std::uint64_t& seen, OnMessage&& on_message, OnMissed&& on_missed) const noexcept {
    const std::uint64_t newest = generation<T>();
    for (std::uint64_t g = seen + 1; g <= newest; ++g) {
      const ReadResult<T> r = read<T>(g);
      if (r.ok()) {
        on_message(r.msg);
      } else if (r.status == ReadStatus::kMissed) {
        on_missed(r.missed);
        g += r.missed > 0 ? r.missed - 1 : 0;
      }
    }
    seen = newest;
  }

  /// Start-up only (allocates). Delivery starts with the first generation posted after this call.
  template <Message T>
  SubscriptionId subscribe(std::function<void(const T&)> callback, Delivery d = Delivery::kCycle) {
    return subscribe<T>(
        [cb = std::move(callback)](const T& msg, const DeliveryInfo&) { cb(msg); }, d);
  }
  template <Message T>
  SubscriptionId subscribe(std::function<void(const T&, const DeliveryInfo&)> callback,
                           Delivery d = Delivery::kCycle) {
    check_can_subscribe();
    auto& ch = channel<T>();
    auto sub = std::make_unique<Sub<T>>();
    sub->callback = std::move(callback);
    sub->last = ch.ring.generation();
    const SubscriptionId id{static_cast<std::uint32_t>(missed_counters_.size())};
    sub->id = id;
    missed_counters_.push_back(&sub->missed_total);
    (d == Delivery::kCycle ? ch.cycle_subs : ch.tool_subs).push_back(std::move(sub));
    return id;
  }

  /// Delivers the kCycle subscriptions (see the dispatch rule above). No allocation.
  void dispatch() noexcept;

  /// Generations a subscription has missed in total so far (safe from any thread).
  [[nodiscard]] std::uint64_t missed(SubscriptionId id) const noexcept;

  /// Starts / stops the thread that delivers kToolThread subscriptions, polling every `period`.
  /// The writer never waits for it. stop is idempotent; the destructor stops it too.
  void start_tool_thread(std::chrono::milliseconds period = std::chrono::milliseconds{2});
  void stop_tool_thread() noexcept;
  [[nodiscard]] bool tool_thread_running() const noexcept;

  // ---- by name, for tools (a test harness impersonating a module, a console, the network) ---

  /// Parses text as the type named type_name and posts it; on any error posts nothing.
  Status post_text(std::string_view type_name, std::string_view text);
  /// description() of the newest message of the named type.
  [[nodiscard]] Result<std::string> describe_newest(std::string_view type_name) const;
  /// Decodes one binary message (any type, by its header) and posts it; on error posts nothing.
  Status post_binary(std::span<const std::byte> bytes);

 private:
  template <class T>
  struct Sub {
    std::function<void(const T&, const DeliveryInfo&)> callback;
    std::uint64_t last = 0;  // generation last delivered or skipped
    std::uint64_t lost = 0;  // generations skipped since the last delivery
    std::atomic<std::uint64_t> missed_total{0};
    SubscriptionId id;
  };

  template <class T>
  struct Channel {
    explicit Channel(std::size_t depth) : ring(depth) {}
    Ring<T> ring;
    std::vector<std::unique_ptr<Sub<T>>> cycle_subs;
    std::vector<std::unique_ptr<Sub<T>>> tool_subs;
  };

  template <class L>
  struct Channels;
  template <class... Ts>
  struct Channels<TypeList<Ts...>> {
    template <class>
    static std::size_t same(std::size_t d) noexcept {
      return d;
    }
    explicit Channels(std::size_t depth) : all(same<Ts>(depth)...) {}
    std::tuple<Channel<Ts>...> all;
  };

  template <class T>
  Channel<T>& channel() noexcept {
    return std::get<Channel<T>>(channels_.all);
  }
  template <class T>
  const Channel<T>& channel() const noexcept {
    return std::get<Channel<T>>(channels_.all);
  }

  /// Delivers every generation since each subscription's last one. Shared by both deliveries.
  template <class T>
  static void deliver(const Ring<T>& ring, std::vector<std::unique_ptr<Sub<T>>>& subs) noexcept {
    for (auto& sub : subs) {
      const std::uint64_t head = ring.generation();
      while (sub->last < head) {
        const ReadResult<T> r = ring.read(sub->last + 1);
        if (r.status == ReadStatus::kMissed) {
          // May jump past `head` (the writer kept going); the loss is reported with the next
          // delivery, even if that is in a later pass.
          sub->lost += r.missed;
          sub->missed_total.fetch_add(r.missed, std::memory_order_relaxed);
          sub->last += r.missed;
          continue;
        }
        sub->last = r.generation;
        const DeliveryInfo info{r.generation, sub->lost};
        sub->lost = 0;
        sub->callback(r.msg, info);
      }
    }
  }

  /// Posts a parsed or decoded message, or passes its error on (posting nothing).
  template <class T>
  Status post_result(const Result<T>& msg) {
    if (!msg) return Error{msg.error()};
    post(*msg);
    return Status{};
  }

  void check_can_subscribe() const;
  void deliver_tool_subscriptions() noexcept;
  friend class ToolThread;

  std::size_t depth_;
  Channels<AllMessages> channels_;
  std::vector<const std::atomic<std::uint64_t>*> missed_counters_;  // by SubscriptionId
  std::atomic<bool> frozen_{false};  // set by the first dispatch() / start_tool_thread()
  std::unique_ptr<ToolThread> tool_;
};

/// Mi-Pal's Type_t: a typed handle on one message type of one whiteboard (alias Name_t).
template <class T>
class Handle {
 public:
  explicit Handle(Whiteboard& wb) noexcept : wb_(&wb) {}
  void set(const T& v) noexcept { wb_->post(v); }
  [[nodiscard]] T get() const noexcept { return wb_->get<T>(); }
  [[nodiscard]] std::uint64_t generation() const noexcept { return wb_->generation<T>(); }
  [[nodiscard]] bool has_new(std::uint64_t since) const noexcept { return wb_->has_new<T>(since); }
  [[nodiscard]] ReadResult<T> read(std::uint64_t gen) const noexcept { return wb_->read<T>(gen); }

 private:
  Whiteboard* wb_;
};

}  // namespace ringlet::wb
