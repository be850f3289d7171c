#pragma once
// One message type's generations: a ring of slots, each guarded by a sequence number (a seqlock),
// written by one thread and read by any number of others without locks or allocation.
//
// Generation g (1, 2, ...) lives in slot (g - 1) % depth. A slot's sequence is 2g - 1 while
// generation g is being written and 2g once it is complete, so a reader knows both whether the
// slot is stable and *which* generation it holds. The payload is stored as 64-bit atomic words,
// so every access is an atomic one: there is no data race for TSan (or the C++ memory model) to
// find, and no fences are needed:
//   writer: seq = 2g-1 (relaxed); words (release); seq = 2g (release); head = g (release)
//   reader: s1 = seq (acquire); words (acquire); s2 = seq (relaxed); valid iff s1 == s2 == 2g
// If any word the reader loaded came from a later write, that write's release ordered its
// "seq = odd" store before it, and the reader's acquire load of the word orders its s2 load
// after it, so s2 != s1 and the copy is thrown away. A torn message is never returned.
#include <array>
#include <atomic>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <type_traits>

namespace ringlet::wb {

enum class ReadStatus : std::uint8_t {
  kOk,      // msg holds the generation asked for
  kMissed,  // that generation (and `missed - 1` after it) was overwritten; read gen + missed next
  kNotYet,  // not posted yet
};

template <class T>
struct ReadResult {
  ReadStatus status = ReadStatus::kNotYet;
  std::uint64_t generation = 0;  // the generation asked for
  std::uint64_t missed = 0;      // kMissed: how many generations from `generation` on are lost
  T msg{};
  [[nodiscard]] bool ok() const noexcept { return status == ReadStatus::kOk; }
};

static_assert(std::atomic<std::uint64_t>::is_always_lock_free,
              "the seqlock payload relies on lock-free 64-bit atomics (true on x86-64, aarch64)");

template <class T>
class Ring {
  static_assert(std::is_trivially_copyable_v<T>);
  static constexpr std::size_t kWords = (sizeof(T) + 7) / 8;
  using Words = std::array<std::uint64_t, kWords>;

  // Own cache line per slot: the writer filling slot k does not disturb readers of slot k - 1.
  struct alignas(64) Slot {
    std::atomic<std::uint64_t> seq{0};
    std::array<std::atomic<std::uint64_t>, kWords> words{};
  };

 public:
  /// depth is rounded up to a power of two (at least 2) so the slot index is a mask.
  explicit Ring(std::size_t depth)
      : depth_(std::bit_ceil(depth < 2 ? std::size_t{2} : depth)),
        slots_(std::make_unique<Slot[]>(depth_)) {}

  [[nodiscard]] std::size_t depth() const noexcept { return depth_; }

  /// Generations posted so far (the newest one's number).
  [[nodiscard]] std::uint64_t generation() const noexcept {
    return head_.load(std::memory_order_acquire);
  }

  /// Single writer per ring. Wait-free, no allocation.
  void post(const T& msg) noexcept {
    const std::uint64_t g = head_.load(std::memory_order_relaxed) + 1;
    Slot& s = slot(g);
    Words buf{};
    std::memcpy(buf.data(), &msg, sizeof(T));
    s.seq.store(2 * g - 1, std::memory_order_relaxed);
    for (std::size_t i = 0; i < kWords; ++i) s.words[i].store(buf[i], std::memory_order_release);
    s.seq.store(2 * g, std::memory_order_release);
    head_.store(g, std::memory_order_release);
  }

  /// Generation gen, if still held. Lock-free; never blocks the writer.
  [[nodiscard]] ReadResult<T> read(std::uint64_t gen) const noexcept {
    ReadResult<T> r;
    r.generation = gen;
    const std::uint64_t head = generation();
    if (gen == 0 || gen > head) return r;  // kNotYet (generation 0 never exists)
    if (gen < oldest(head)) return missed(r, oldest(head));

    const Slot& s = slot(gen);
    const std::uint64_t want = 2 * gen;
    if (s.seq.load(std::memory_order_acquire) != want) return overwritten(r);
    Words buf;
    for (std::size_t i = 0; i < kWords; ++i) buf[i] = s.words[i].load(std::memory_order_acquire);
    if (s.seq.load(std::memory_order_relaxed) != want) return overwritten(r);
    std::memcpy(static_cast<void*>(&r.msg), buf.data(), sizeof(T));  // T is trivially copyable
    r.status = ReadStatus::kOk;
    return r;
  }

  /// The newest message (T{} if none). Retries only if the writer laps the whole ring mid-copy.
  [[nodiscard]] T newest() const noexcept {
    for (;;) {
      const std::uint64_t head = generation();
      if (head == 0) return T{};
      ReadResult<T> r = read(head);
      if (r.ok()) return r.msg;
    }
  }

 private:
  [[nodiscard]] std::uint64_t oldest(std::uint64_t head) const noexcept {
    return head >= depth_ ? head - depth_ + 1 : 1;
  }
  static ReadResult<T> missed(ReadResult<T> r, std::uint64_t first_kept) noexcept {
    r.status = ReadStatus::kMissed;
    r.missed = first_kept - r.generation;
    return r;
  }
  // The slot moved on while we looked: generation + depth (at least) is being or was written, so
  // generation itself and all before the oldest one still held are gone.
  ReadResult<T> overwritten(ReadResult<T> r) const noexcept {
    const std::uint64_t keep = oldest(generation());
    return missed(r, keep > r.generation ? keep : r.generation + 1);
  }
  Slot& slot(std::uint64_t gen) noexcept { return slots_[(gen - 1) & (depth_ - 1)]; }
  const Slot& slot(std::uint64_t gen) const noexcept { return slots_[(gen - 1) & (depth_ - 1)]; }

  std::size_t depth_;
  std::unique_ptr<Slot[]> slots_;
  alignas(64) std::atomic<std::uint64_t> head_{0};
};

}  // namespace ringlet::wb
