#pragma once
// The closed list both planners share: states (bit sets of a fixed number of words) stored once
// each, numbered in insertion order, found again by hash. Sized at construction; clear() is
// O(1) (slots carry the epoch that wrote them), so a restart costs nothing in the cycle.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace ringlet::pddl {

class StateTable {
 public:
  static constexpr std::int32_t kFull = -1;

  /// Room for `max_states` states of up to `max_words` words.
  StateTable(std::size_t max_states, std::size_t max_words);

  /// Empties the table for states of `words` words (at most max_words).
  void clear(std::size_t words) noexcept;

  struct Insert {
    std::int32_t index = kFull;  ///< kFull when the table is full
    bool inserted = false;       ///< false: the state was there already
  };
  [[nodiscard]] Insert insert(std::span<const std::uint64_t> state) noexcept;

  [[nodiscard]] std::span<const std::uint64_t> state(std::int32_t index) const noexcept;
  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  [[nodiscard]] std::size_t capacity() const noexcept { return max_states_; }

 private:
  [[nodiscard]] std::uint64_t hash(std::span<const std::uint64_t> state) const noexcept;

  std::size_t max_states_;
  std::size_t max_words_;
  std::size_t words_ = 0;
  std::size_t size_ = 0;
  std::uint32_t epoch_ = 1;
  std::size_t mask_;
  std::vector<std::uint64_t> states_;
  std::vector<std::int32_t> slot_index_;
  std::vector<std::uint32_t> slot_epoch_;
};

}  // namespace ringlet::pddl
