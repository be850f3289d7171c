#pragma once
// A seeded model of an unreliable link (UDP between a machine and a service on other hosts, as
// Mi-Pal distributed their whiteboard): every message pushed is dropped with probability `drop`,
// else delivered after 0..max_delay activations, and with probability `duplicate` delivered a
// second time after its own delay; so messages are lost, repeated and reordered. With the
// defaults (nothing dropped, no delay) it is a plain pipe. Fixed capacity, no allocation after
// construction; a full link drops (counted). One seeded generator: the same seed and pushes give
// the same deliveries on every host.
#include <array>
#include <cstddef>
#include <cstdint>

namespace ringlet::firmware {

struct LossyLinkSettings {
  double drop = 0.0;       ///< probability a message is lost
  double duplicate = 0.0;  ///< probability a delivered message arrives twice
  int max_delay = 0;       ///< activations a message may take (uniform 0..max_delay): reordering
  std::uint64_t seed = 1;

  [[nodiscard]] bool perfect() const noexcept { return drop <= 0.0 && duplicate <= 0.0 && max_delay <= 0; }
};

struct LossyLinkCounts {
  std::uint64_t pushed = 0, delivered = 0, dropped = 0, duplicated = 0, overflowed = 0;
};

template <typename T, std::size_t Capacity = 32>
class LossyLink {
 public:
  explicit LossyLink(const LossyLinkSettings& s = {}) noexcept : s_(s), rng_(s.seed ^ 0x9E3779B97F4A7C15ULL) {}

  /// Sends `m` at activation `now`.
  void push(const T& m, std::uint64_t now) noexcept {
    ++counts_.pushed;
    if (chance(s_.drop)) {
      ++counts_.dropped;
      return;
    }
    enqueue(m, now + delay());
    if (chance(s_.duplicate)) {
      ++counts_.duplicated;
      enqueue(m, now + delay());
    }
  }

  /// The next message due by activation `now` (earliest due first, then first sent), or false.
  bool pop(std::uint64_t now, T& out) noexcept {
    std::size_t best = Capacity;
    for (std::size_t i = 0; i < Capacity; ++i) {
      if (!slots_[i].used || slots_[i].due > now) continue;
      if (best == Capacity || slots_[i].due < slots_[best].due ||
          (slots_[i].due == slots_[best].due && slots_[i].order < slots_[best].order)) {
        best = i;
      }
    }
    if (best == Capacity) return false;
    out = slots_[best].message;
    slots_[best].used = false;
    ++counts_.delivered;
    return true;
  }

  [[nodiscard]] const LossyLinkCounts& counts() const noexcept { return counts_; }

 private:
  struct Slot {
    T message{};
    std::uint64_t due = 0, order = 0;
    bool used = false;
  };

  void enqueue(const T& m, std::uint64_t due) noexcept {
    for (Slot& slot : slots_) {
      if (slot.used) continue;
      slot = Slot{m, due, next_order_++, true};
      return;
    }
    ++counts_.overflowed;
  }
  // splitmix64: small, seeded, the same on every platform.
  std::uint64_t next() noexcept {
    std::uint64_t z = (rng_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31U);
  }
  bool chance(double p) noexcept {
    if (p <= 0.0) return false;
    return static_cast<double>(next() >> 11U) * 0x1.0p-53 < p;
  }
  std::uint64_t delay() noexcept {
    if (s_.max_delay <= 0) return 0;
    return next() % static_cast<std::uint64_t>(s_.max_delay + 1);
  }

  LossyLinkSettings s_;
  std::uint64_t rng_;
  std::array<Slot, Capacity> slots_{};
  std::uint64_t next_order_ = 0;
  LossyLinkCounts counts_{};
};

}  // namespace ringlet::firmware
