#pragma once
// The bridge: publishes the whiteboard on DDS from its own non-real-time thread.
//
// It reads each type by generation (Whiteboard::read, lock-free: the cycle never waits for it and
// never sees it) and writes every generation it has not sent yet, converted by topics.hpp, with
// the robot id and the generation in the sample. What it could not send is counted per type:
//   missed        generations the whiteboard's ring overwrote before the bridge read them
//   rate_skipped  generations left out on purpose by the type's rate limit (the newest is sent)
//   failed        dds_write errors
// These totals, the remote writes and the matched monitors go on the whiteboard as
// wb::BridgeHealth once per health_period (through the inbox, like a remote write).
// Everything DDS needs (participant, topics, writers) is created in the constructor; the thread
// only reads, converts into a sample on its own stack and writes.
//
// Remote writes (off by default): a monitor writes a request to the robot's request topic
// (topics.hpp, request_topic_name) with the robot's id in it. The bridge takes the requests
// addressed to its robot at every pump, refuses types not on the allow-list (unauthorized) and
// samples that do not validate (malformed: from_sample, and the type's own check, e.g. an
// FsmControl must name a machine that exists), and queues the rest in the Inbox, which the cycle
// empties onto the whiteboard at one defined point. Refusals are counted and described on `log`;
// nothing of a refused request reaches the whiteboard.
//
// Lockstep runs: the executive may call flush() at a frame boundary to wait until every reliable
// sample has been acknowledged by the monitors that are listening, so a monitor of a simulated run
// loses nothing however fast the simulation runs (remote/README.md, "Pacing").
#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <thread>
#include <vector>

#include "ringlet/hal/monotonic_clock.hpp"
#include "ringlet/remote/domain.hpp"
#include "ringlet/remote/inbox.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::remote {

struct TypeRate {
  bool publish = true;
  std::chrono::nanoseconds min_period{0};  // 0: every generation; else at most one sample per period
};

struct BridgeConfig {
  std::uint16_t robot = 0;
  DomainConfig domain{};
  std::chrono::microseconds poll_period{2000};
  std::array<TypeRate, wb::kTypeCount> types{};  // by position in wb::kTypes
  // Remote writes: off unless a type is on this allow-list (by position in wb::kTypes).
  std::array<bool, wb::kTypeCount> accept{};
  std::vector<std::string> machines;  // the names an FsmControl may address (empty: any name)
  std::size_t inbox_capacity = 16;    // accepted requests waiting for the cycle, per type
  std::ostream* log = nullptr;        // refusals are described here (the first 20, then every 100th)
  // How often the bridge posts its wb::BridgeHealth through the inbox (on pump's time line);
  // 0: never. Whoever delivers the inbox puts it on the whiteboard.
  std::chrono::nanoseconds health_period{std::chrono::seconds{1}};
};

/// What became of the requests addressed to this robot (requests to other robots are not seen).
struct RequestCounts {
  std::uint64_t accepted = 0;      // validated and queued for the cycle
  std::uint64_t unauthorized = 0;  // a type not on the allow-list
  std::uint64_t malformed = 0;     // a value without whiteboard meaning, or refused by the type's check
  std::uint64_t dropped = 0;       // accepted, but the type's queue was full
  RequestCounts& operator+=(const RequestCounts& o) noexcept {
    accepted += o.accepted;
    unauthorized += o.unauthorized;
    malformed += o.malformed;
    dropped += o.dropped;
    return *this;
  }
};

struct TypeCounts {
  std::uint64_t sent = 0;
  std::uint64_t missed = 0;
  std::uint64_t rate_skipped = 0;
  std::uint64_t failed = 0;
  TypeCounts& operator+=(const TypeCounts& o) noexcept {
    sent += o.sent;
    missed += o.missed;
    rate_skipped += o.rate_skipped;
    failed += o.failed;
    return *this;
  }
};

class Bridge {
 public:
  /// Joins the domain and creates a writer per published type (throws RemoteError).
  Bridge(const wb::Whiteboard& board, BridgeConfig config);
  ~Bridge();
  Bridge(const Bridge&) = delete;
  Bridge& operator=(const Bridge&) = delete;

  /// Starts / stops the thread that calls pump() every poll period. stop() pumps once more, so
  /// everything posted before it is sent.
  void start();
  void stop() noexcept;
  [[nodiscard]] bool running() const noexcept { return thread_.joinable(); }

  /// One pass over every published type; returns the samples written. Called by the thread, or
  /// (without the thread) by a caller that wants to choose when. Rate limits are judged on `now`:
  /// the steady clock by default; a lockstep run passes its virtual frame time, so what a
  /// rate-limited topic carries is the same on every host.
  std::size_t pump() noexcept;
  std::size_t pump(std::chrono::nanoseconds now) noexcept;

  /// Waits up to `timeout` until every reliable sample written so far is acknowledged by every
  /// matched reader; false on timeout.
  bool flush(std::chrono::milliseconds timeout) noexcept;

  /// Readers matched to T's writer (0 when T is not published).
  template <wb::Message T>
  [[nodiscard]] std::uint32_t matched_readers() const noexcept {
    return matched(wb::kIndexOf<T>);
  }

  [[nodiscard]] TypeCounts counts(wb::TypeId type) const noexcept;
  [[nodiscard]] TypeCounts totals() const noexcept;
  /// CPU time spent in pump() so far (the calling thread's CPU clock), and how many pumps.
  [[nodiscard]] std::chrono::nanoseconds cpu_time() const noexcept { return std::chrono::nanoseconds{cpu_ns_.load(std::memory_order_relaxed)}; }
  [[nodiscard]] std::uint64_t pumps() const noexcept { return pumps_.load(std::memory_order_relaxed); }
  [[nodiscard]] RequestCounts requests(wb::TypeId type) const noexcept;
  [[nodiscard]] RequestCounts request_totals() const noexcept;
  /// The accepted remote writes, for the cycle to deliver (Inbox::deliver) at its defined point.
  [[nodiscard]] Inbox& inbox() noexcept { return inbox_; }
  [[nodiscard]] const BridgeConfig& config() const noexcept { return config_; }
  [[nodiscard]] Participant& participant() noexcept { return participant_; }

 private:
  struct Slot {
    dds_entity_t writer = 0;
    std::uint64_t last = 0;  // the newest generation handled (sent, missed or skipped)
    std::optional<std::chrono::nanoseconds> last_sent;  // when the last sample was written (pump's time line)
    std::atomic<std::uint64_t> sent{0};
    std::atomic<std::uint64_t> missed{0};
    std::atomic<std::uint64_t> rate_skipped{0};
    std::atomic<std::uint64_t> failed{0};
    dds_entity_t request_reader = 0;
    std::atomic<std::uint64_t> accepted{0};
    std::atomic<std::uint64_t> unauthorized{0};
    std::atomic<std::uint64_t> malformed{0};
    std::atomic<std::uint64_t> dropped{0};
  };
  template <wb::Message T>
  std::size_t pump_type(std::chrono::nanoseconds now) noexcept;
  template <wb::Message T>
  bool write(Slot& slot, const T& msg, std::uint64_t generation) noexcept;
  template <wb::Message T>
  void take_requests() noexcept;
  void refuse(std::string_view type, std::uint64_t request, const std::string& why) noexcept;
  void post_health(std::chrono::nanoseconds now) noexcept;
  [[nodiscard]] std::uint32_t matched(std::size_t index) const noexcept;
  [[nodiscard]] const Slot* slot_of(wb::TypeId type) const noexcept;

  const wb::Whiteboard& board_;
  BridgeConfig config_;
  Participant participant_;
  std::array<Slot, wb::kTypeCount> slots_{};
  Inbox inbox_;
  std::uint64_t refusals_ = 0;
  std::optional<std::chrono::nanoseconds> last_health_;
  hal::ThreadStopwatch stopwatch_;
  std::atomic<std::int64_t> cpu_ns_{0};
  std::atomic<std::uint64_t> pumps_{0};
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace ringlet::remote
