#pragma once
// The whiteboard log: every message posted on a whiteboard, in the order dispatch() delivered it,
// with the frame it was delivered in, its generation and the generations the ring lost before it,
// each in the binary codec's form (binary.hpp). A replayed run's log can then be compared with the
// recorded run's: the first difference names the message and shows both as description() text.
//
// MessageLogger subscribes to every type with Delivery::kCycle, so messages arrive inside
// dispatch(), on the executive's thread, in the whiteboard's deterministic order (type id order,
// generations oldest first): identical runs give byte-identical logs. Subscriptions are made at
// start-up, so the logger is constructed before the first dispatch(). A callback copies the
// encoded message into a slot preallocated at construction and hands it through a bounded
// single-producer single-consumer queue to a writer thread; it never allocates, locks or writes.
// When the queue is full: kLossless waits for a free slot (lockstep runs, where time is virtual),
// kDropOnFull drops the message and counts it (real clock); the log marks the gap and a log with
// gaps never compares equal.
//
// File layout (little-endian; see whiteboard/README.md):
//   header  "RLWBLOG\0" | u32 version (1) | u32 type count | per type: u16 id, u16 version, u32 payload bytes
//   records u8 kind, then
//     1 message: u64 frame | u64 generation | u64 missed | the encoded message (8-byte wire header + payload)
//     2 gap:     u64 frame | u64 messages dropped just before the next record
//     3 end:     u64 messages logged | u64 messages dropped
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ringlet/whiteboard/binary.hpp"
#include "ringlet/whiteboard/messages.hpp"
#include "ringlet/whiteboard/result.hpp"

namespace ringlet::wb {

class Whiteboard;

inline constexpr std::string_view kMessageLogMagic{"RLWBLOG\0", 8};
inline constexpr std::uint32_t kMessageLogVersion = 1;

/// The largest encoded message of any schema type (header + payload).
inline constexpr std::size_t kMaxEncodedMessageBytes = [] {
  std::size_t n = 0;
  for_each_type([&n](auto type) {
    using T = typename decltype(type)::type;
    n = std::max(n, encoded_size<T>());
  });
  return n;
}();

enum class MessageLogMode : std::uint8_t { kLossless, kDropOnFull };

struct MessageLogOptions {
  MessageLogMode mode = MessageLogMode::kLossless;
  std::size_t slots = 1024;  // messages in flight (kMaxEncodedMessageBytes + 32 bytes each)
};

struct MessageLogStatus {
  std::string error;  // "<path>: cannot write whiteboard log: <errno text>", or empty
  std::uint64_t logged = 0;
  std::uint64_t dropped = 0;
  [[nodiscard]] bool ok() const noexcept { return error.empty(); }
};

class MessageLogger {
 public:
  /// Subscribes to every message type on `wb` (start-up only: throws std::logic_error after the
  /// first dispatch()), creates the file (throws std::runtime_error "<path>: cannot create
  /// whiteboard log: <why>"), writes its header and starts the writer thread. The subscriptions
  /// stay on the whiteboard after the logger is gone; they do nothing then.
  MessageLogger(Whiteboard& wb, const std::filesystem::path& path, MessageLogOptions options = {});
  ~MessageLogger();
  MessageLogger(const MessageLogger&) = delete;
  MessageLogger& operator=(const MessageLogger&) = delete;

  /// The frame the messages delivered from now on belong to: call it each cycle before dispatch()
  /// (the executive's frame index). Without it every message is logged at frame 0.
  void set_frame(std::uint64_t frame) noexcept;

  /// Writes what is queued and the end record, closes the file, joins the writer. Call it after
  /// the last dispatch(). Idempotent; the destructor calls it. Never throws.
  MessageLogStatus stop() noexcept;
  [[nodiscard]] MessageLogStatus status() const;

  struct State;

 private:
  std::shared_ptr<State> state_;
};

/// One logged message.
struct LoggedMessage {
  std::uint64_t frame = 0;
  std::uint64_t generation = 0;
  std::uint64_t missed = 0;
  TypeId type{};
  std::vector<std::byte> bytes;  // the encoded message (binary.hpp)
  /// "BallBelief generation 3 (frame 5): true,1,2,0.5,false" (plus ", 2 missed before it").
  [[nodiscard]] std::string describe() const;
};

struct MessageLog {
  std::vector<LoggedMessage> messages;
  std::uint64_t dropped = 0;  // messages the logger dropped (queue full)
  bool complete = false;      // an end record closes the log
};

/// The largest whiteboard log read_message_log reads by default.
inline constexpr std::size_t kMaxMessageLogBytes = std::size_t{1} << 30;

/// Reads a whole whiteboard log (a regular file of at most max_bytes). The error reads
/// "<path>: <what is wrong> at byte N"; every message is decoded (so a bad one is refused here).
[[nodiscard]] Result<MessageLog> read_message_log(const std::filesystem::path& path,
                                                  std::size_t max_bytes = kMaxMessageLogBytes);
/// The same, from bytes already in memory (`name` stands for the path in messages).
[[nodiscard]] Result<MessageLog> parse_message_log(std::span<const std::byte> bytes, std::string_view name);

/// Leaves out the messages that carry the host's measurements (ExecutiveTiming: measured task
/// times), which differ between any two runs by nature; what is left is what the controller did.
void drop_host_measurements(MessageLog& log);

/// The first difference between two logs, as one line, or nullopt when they are equal (same
/// messages, frames, generations and losses, neither dropped anything).
[[nodiscard]] std::optional<std::string> first_difference(const MessageLog& expected, const MessageLog& actual);

}  // namespace ringlet::wb
