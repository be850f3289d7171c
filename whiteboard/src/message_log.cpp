#include "ringlet/whiteboard/message_log.hpp"

#include <array>
#include <chrono>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "ringlet/hal/log_file.hpp"
#include "ringlet/hal/read_file.hpp"
#include "ringlet/hal/spsc_cursor.hpp"
#include "ringlet/whiteboard/whiteboard.hpp"

namespace ringlet::wb {
namespace {

enum class LogKind : std::uint8_t { kMessage = 1, kGap = 2, kEnd = 3 };

constexpr std::size_t kFlushBytes = 1u << 20;
constexpr auto kIdleSleep = std::chrono::milliseconds{1};
constexpr std::size_t kTypeEntryBytes = 8;
constexpr std::size_t kMessagePrefixBytes = 24;  // frame, generation, missed

void put(std::vector<std::byte>& out, std::uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<std::byte>(v >> (8 * i)));
}
std::uint64_t get(const std::byte* p, int bytes) {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v |= std::to_integer<std::uint64_t>(p[i]) << (8 * i);
  return v;
}

/// Decodes the encoded message (any schema type) and calls f(msg); the error otherwise.
template <class F>
Status with_decoded(std::span<const std::byte> bytes, F&& f) {
  Result<WireHeader> header = peek_header(bytes);
  if (!header) return Error{header.error()};
  Status status = Error{"unknown type id " + std::to_string(to_underlying(header->id))};
  for_each_type([&](auto type) {
    using T = typename decltype(type)::type;
    if (T::kId != header->id) return;
    Result<T> msg = decode<T>(bytes);
    if (!msg) {
      status = Error{msg.error()};
    } else {
      f(*msg);
      status = Status{};
    }
  });
  return status;
}

}  // namespace

// ---- the logger ---------------------------------------------------------------------------------

struct MessageLogger::State {
  struct Slot {
    std::uint64_t frame = 0;
    std::uint64_t generation = 0;
    std::uint64_t missed = 0;
    std::uint64_t dropped_before = 0;
    std::size_t size = 0;
    std::array<std::byte, kMaxEncodedMessageBytes> bytes{};
  };

  State(std::string path, MessageLogOptions opts)
      : file(std::move(path), "whiteboard log"), options(opts), cursor(opts.slots) {}

  hal::LogFile file;
  MessageLogOptions options;
  hal::SpscCursor cursor;
  std::vector<Slot> slots;

  std::atomic<std::uint64_t> frame{0};
  std::atomic<bool> active{true};
  std::uint64_t pending_drops = 0;  // producer only

  std::atomic<bool> stopping{false};
  std::atomic<std::uint64_t> logged{0};
  std::atomic<std::uint64_t> dropped{0};
  mutable std::mutex error_mutex;
  std::string error;
  std::thread writer;
  bool stopped = false;

  std::vector<std::byte> out;
  std::uint64_t gap_total = 0;

  template <class T>
  void on_message(const T& msg, const DeliveryInfo& info) noexcept {
    if (!active.load(std::memory_order_relaxed)) return;
    if (!cursor.can_write()) {
      if (options.mode == MessageLogMode::kDropOnFull) {
        ++pending_drops;
        dropped.fetch_add(1, std::memory_order_relaxed);
        return;
      }
      cursor.wait_writable();
    }
    Slot& s = slots[cursor.write_slot()];
    s.frame = frame.load(std::memory_order_relaxed);
    s.generation = info.generation;
    s.missed = info.missed;
    s.dropped_before = pending_drops;
    pending_drops = 0;
    s.size = encode(msg, s.bytes);
    cursor.publish();
  }

  void set_error(std::string e) {
    const std::lock_guard lock(error_mutex);
    if (error.empty()) error = std::move(e);
  }

  void flush() {
    if (!file.write_all(out.data(), out.size())) set_error(file.error());
    out.clear();
  }

  void append_gap(std::uint64_t at_frame, std::uint64_t count) {
    out.push_back(static_cast<std::byte>(LogKind::kGap));
    put(out, at_frame, 8);
    put(out, count, 8);
    gap_total += count;
  }

  void run() {
    for (;;) {
      if (cursor.can_read()) {
        const Slot& s = slots[cursor.read_slot()];
        if (s.dropped_before > 0) append_gap(s.frame, s.dropped_before);
        out.push_back(static_cast<std::byte>(LogKind::kMessage));
        put(out, s.frame, 8);
        put(out, s.generation, 8);
        put(out, s.missed, 8);
        out.insert(out.end(), s.bytes.begin(), s.bytes.begin() + static_cast<std::ptrdiff_t>(s.size));
        cursor.release();
        logged.fetch_add(1, std::memory_order_relaxed);
        if (out.size() >= kFlushBytes) flush();
        continue;
      }
      flush();
      if (stopping.load(std::memory_order_acquire)) {
        if (cursor.can_read()) continue;
        break;
      }
      std::this_thread::sleep_for(kIdleSleep);
    }
    // Drops after the last queued message (the producer has stopped: the counter is final).
    const std::uint64_t total = dropped.load(std::memory_order_relaxed);
    if (total > gap_total) append_gap(frame.load(std::memory_order_relaxed), total - gap_total);
    out.push_back(static_cast<std::byte>(LogKind::kEnd));
    put(out, logged.load(std::memory_order_relaxed), 8);
    put(out, gap_total, 8);
    flush();
  }

  void open_and_start() {
    if (options.slots == 0) throw std::invalid_argument("MessageLogOptions: slots must be at least 1");
    slots.resize(options.slots);
    out.reserve(kFlushBytes + kMaxEncodedMessageBytes + 64);
    if (std::string refused = file.create(); !refused.empty()) throw std::runtime_error(refused);
    for (char c : kMessageLogMagic) out.push_back(static_cast<std::byte>(c));
    put(out, kMessageLogVersion, 4);
    put(out, kTypeCount, 4);
    for_each_type([this](auto type) {
      using T = typename decltype(type)::type;
      put(out, to_underlying(T::kId), 2);
      put(out, T::kVersion, 2);
      put(out, payload_size<T>(), 4);
    });
    flush();
    if (file.failed()) {
      file.close();
      throw std::runtime_error(file.error());
    }
    writer = std::thread([this] { run(); });
  }

  void stop() noexcept {
    if (stopped) return;
    stopped = true;
    active.store(false, std::memory_order_relaxed);
    stopping.store(true, std::memory_order_release);
    writer.join();
    if (!file.close()) set_error(file.error());
  }

  MessageLogStatus status() const {
    MessageLogStatus st;
    {
      const std::lock_guard lock(error_mutex);
      st.error = error;
    }
    st.logged = logged.load(std::memory_order_relaxed);
    st.dropped = dropped.load(std::memory_order_relaxed);
    return st;
  }
};

MessageLogger::MessageLogger(Whiteboard& wb, const std::filesystem::path& path, MessageLogOptions options)
    : state_(std::make_shared<State>(path.string(), options)) {
  // Subscribe first: a whiteboard that is already dispatching refuses, before a file is created.
  for_each_type([this, &wb](auto type) {
    using T = typename decltype(type)::type;
    wb.subscribe<T>(
        std::function<void(const T&, const DeliveryInfo&)>(
            [state = state_](const T& msg, const DeliveryInfo& info) { state->on_message(msg, info); }),
        Delivery::kCycle);
  });
  state_->open_and_start();
}

MessageLogger::~MessageLogger() { state_->stop(); }

void MessageLogger::set_frame(std::uint64_t frame) noexcept { state_->frame.store(frame, std::memory_order_relaxed); }

MessageLogStatus MessageLogger::stop() noexcept {
  state_->stop();
  try {
    return state_->status();
  } catch (...) {
    return MessageLogStatus{};
  }
}

MessageLogStatus MessageLogger::status() const { return state_->status(); }

// ---- reading and comparing ----------------------------------------------------------------------

std::string LoggedMessage::describe() const {
  const auto info = find_type(type);
  std::string text;
  const Status s = with_decoded(bytes, [&text](const auto& msg) { text = msg.description(); });
  std::string out = std::string(info ? info->name : "unknown type") + " generation " + std::to_string(generation) +
                    " (frame " + std::to_string(frame);
  if (missed > 0) out += ", " + std::to_string(missed) + " missed before it";
  out += "): ";
  out += s ? text : "<" + s.error() + ">";
  return out;
}

Result<MessageLog> parse_message_log(std::span<const std::byte> bytes, std::string_view name) {
  std::size_t at = 0;
  const auto fail = [&](const std::string& what, std::size_t where) -> Result<MessageLog> {
    return Error{std::string(name) + ": " + what + " at byte " + std::to_string(where)};
  };
  const auto left = [&] { return bytes.size() - at; };
  const auto truncated = [&](const char* what, std::size_t need, std::size_t where) {
    return fail(std::string("truncated ") + what + " (" + std::to_string(need) + " bytes needed, " +
                    std::to_string(left()) + " left)",
                where);
  };

  const std::size_t magic_got = std::min(bytes.size(), kMessageLogMagic.size());
  // (memcmp of an empty span would pass a null pointer: compare only what is there.)
  if (magic_got > 0 && std::memcmp(bytes.data(), kMessageLogMagic.data(), magic_got) != 0) {
    return fail("wrong magic (not a Ringlet whiteboard log)", 0);
  }
  if (bytes.size() < 16) return truncated("header", 16, 0);
  const auto version = static_cast<std::uint32_t>(get(bytes.data() + 8, 4));
  if (version != kMessageLogVersion) {
    return fail("unsupported version " + std::to_string(version) + " (this build reads version " +
                    std::to_string(kMessageLogVersion) + ")",
                8);
  }
  const std::uint64_t types = get(bytes.data() + 12, 4);
  at = 16;
  if (types != kTypeCount) {
    return fail("the log's schema has " + std::to_string(types) + " message types, this build's " +
                    std::to_string(kTypeCount),
                12);
  }
  if (left() < types * kTypeEntryBytes) return truncated("schema table", types * kTypeEntryBytes, at);
  std::optional<std::string> schema_error;
  std::size_t schema_at = 0;
  std::size_t i = 0;
  for_each_type([&](auto type) {
    using T = typename decltype(type)::type;
    const std::byte* p = bytes.data() + at + i * kTypeEntryBytes;
    const auto id = get(p, 2);
    const auto ver = get(p + 2, 2);
    const auto size = get(p + 4, 4);
    if (!schema_error && (id != to_underlying(T::kId) || ver != T::kVersion || size != payload_size<T>())) {
      schema_error = "the log's schema differs from this build's: type " + std::to_string(i) + " is id " +
                     std::to_string(id) + " version " + std::to_string(ver) + " (" + std::to_string(size) +
                     " bytes), this build's " + std::string(T::kName) + " is id " +
                     std::to_string(to_underlying(T::kId)) + " version " + std::to_string(T::kVersion) + " (" +
                     std::to_string(payload_size<T>()) + " bytes)";
      schema_at = at + i * kTypeEntryBytes;
    }
    ++i;
  });
  if (schema_error) return fail(*schema_error, schema_at);
  at += types * kTypeEntryBytes;

  MessageLog log;
  std::uint64_t gaps = 0;
  while (at < bytes.size()) {
    const std::size_t record_at = at;
    if (log.complete) return fail("data after the end record", record_at);
    const auto kind = std::to_integer<std::uint8_t>(bytes[at]);
    ++at;
    if (kind == static_cast<std::uint8_t>(LogKind::kMessage)) {
      if (left() < kMessagePrefixBytes + kWireHeaderSize) {
        return truncated("message record", kMessagePrefixBytes + kWireHeaderSize, record_at);
      }
      LoggedMessage m;
      m.frame = get(bytes.data() + at, 8);
      m.generation = get(bytes.data() + at + 8, 8);
      m.missed = get(bytes.data() + at + 16, 8);
      at += kMessagePrefixBytes;
      const Result<WireHeader> header = peek_header(bytes.subspan(at));
      if (!header) return fail(header.error(), at);
      const auto info = find_type(header->id);
      if (!info) return fail("unknown message type id " + std::to_string(to_underlying(header->id)), at);
      const std::size_t size = kWireHeaderSize + header->payload_size;
      if (size > kMaxEncodedMessageBytes) {
        return fail(std::string(info->name) + " of " + std::to_string(header->payload_size) +
                        " payload bytes is larger than any message",
                    at);
      }
      if (left() < size) return truncated("message record", size, record_at);
      const auto encoded = bytes.subspan(at, size);
      const Status decoded = with_decoded(encoded, [](const auto&) {});
      if (!decoded) return fail(decoded.error(), at);
      m.type = header->id;
      m.bytes.assign(encoded.begin(), encoded.end());
      log.messages.push_back(std::move(m));
      at += size;
    } else if (kind == static_cast<std::uint8_t>(LogKind::kGap) || kind == static_cast<std::uint8_t>(LogKind::kEnd)) {
      const bool gap = kind == static_cast<std::uint8_t>(LogKind::kGap);
      if (left() < 16) return truncated(gap ? "gap record" : "end record", 16, record_at);
      const std::uint64_t a = get(bytes.data() + at, 8);
      const std::uint64_t b = get(bytes.data() + at + 8, 8);
      at += 16;
      if (gap) {
        if (b == 0) return fail("gap record drops nothing", record_at);
        gaps += b;
      } else {
        if (a != log.messages.size() || b != gaps) {
          return fail("end record counts " + std::to_string(a) + " messages and " + std::to_string(b) +
                          " dropped, the log has " + std::to_string(log.messages.size()) + " and " +
                          std::to_string(gaps),
                      record_at);
        }
        log.complete = true;
      }
    } else {
      return fail("unknown record kind " + std::to_string(kind), record_at);
    }
  }
  log.dropped = gaps;
  return log;
}

Result<MessageLog> read_message_log(const std::filesystem::path& path, std::size_t max_bytes) {
  const hal::FileRead file = hal::read_file(path, "whiteboard log", max_bytes);
  if (!file.ok()) return Error{file.error};
  return parse_message_log(std::as_bytes(std::span<const char>(file.bytes.data(), file.bytes.size())),
                           path.string());
}

void drop_host_measurements(MessageLog& log) {
  std::erase_if(log.messages, [](const LoggedMessage& m) { return m.type == ExecutiveTiming::kId; });
}

std::optional<std::string> first_difference(const MessageLog& expected, const MessageLog& actual) {
  if (expected.dropped > 0) {
    return "the expected log dropped " + std::to_string(expected.dropped) +
           " messages (its logger's queue was full): it cannot be compared";
  }
  if (actual.dropped > 0) {
    return "the actual log dropped " + std::to_string(actual.dropped) +
           " messages (its logger's queue was full): it cannot be compared";
  }
  const std::size_t n = std::min(expected.messages.size(), actual.messages.size());
  for (std::size_t i = 0; i < n; ++i) {
    const LoggedMessage& e = expected.messages[i];
    const LoggedMessage& a = actual.messages[i];
    if (e.frame != a.frame || e.type != a.type || e.generation != a.generation || e.missed != a.missed ||
        e.bytes != a.bytes) {
      return "message " + std::to_string(i) + ": expected " + e.describe() + "; got " + a.describe();
    }
  }
  if (expected.messages.size() > n) {
    return "expected " + std::to_string(expected.messages.size()) + " messages, got " + std::to_string(n) +
           "; the first missing is " + expected.messages[n].describe();
  }
  if (actual.messages.size() > n) {
    return "expected " + std::to_string(n) + " messages, got " + std::to_string(actual.messages.size()) +
           "; the first extra is " + actual.messages[n].describe();
  }
  return std::nullopt;
}

}  // namespace ringlet::wb
