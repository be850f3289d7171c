#pragma once
// A binary min-heap of search entries with a fixed capacity (allocated at construction): key
// first, then insertion order, so equal keys leave first-in first-out on every host.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ringlet::pddl {

struct OpenEntry {
  std::int64_t key = 0;
  std::uint64_t order = 0;
  std::int32_t node = 0;
  std::int32_t g = 0;  ///< the node's g when queued: a lower g since makes the entry stale
};

class OpenList {
 public:
  explicit OpenList(std::size_t capacity) : heap_(capacity) {}

  void clear() noexcept { size_ = 0; }
  /// False when full.
  [[nodiscard]] bool push(std::int64_t key, std::int32_t node, std::int32_t g) noexcept;
  [[nodiscard]] OpenEntry pop() noexcept;
  [[nodiscard]] bool empty() const noexcept { return size_ == 0; }
  [[nodiscard]] std::size_t size() const noexcept { return size_; }

 private:
  [[nodiscard]] static bool before(const OpenEntry& a, const OpenEntry& b) noexcept {
    return a.key != b.key ? a.key < b.key : a.order < b.order;
  }

  std::vector<OpenEntry> heap_;
  std::size_t size_ = 0;
  std::uint64_t next_order_ = 0;
};

}  // namespace ringlet::pddl
