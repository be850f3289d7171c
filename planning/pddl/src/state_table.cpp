#include "ringlet/pddl/state_table.hpp"

#include <algorithm>

namespace ringlet::pddl {
namespace {

std::size_t slots_for(std::size_t states) {
  std::size_t n = 16;
  while (n < 2 * states) n *= 2;  // at most half full: probes stay short
  return n;
}

}  // namespace

StateTable::StateTable(std::size_t max_states, std::size_t max_words)
    : max_states_(max_states),
      max_words_(max_words),
      mask_(slots_for(max_states) - 1),
      states_(max_states * max_words),
      slot_index_(slots_for(max_states)),
      slot_epoch_(slots_for(max_states)) {}

void StateTable::clear(std::size_t words) noexcept {
  words_ = std::min(words, max_words_);
  size_ = 0;
  if (++epoch_ == 0) {  // after 2^32 clears: wipe once so an old slot can never look current
    std::fill(slot_epoch_.begin(), slot_epoch_.end(), 0U);
    epoch_ = 1;
  }
}

std::uint64_t StateTable::hash(std::span<const std::uint64_t> state) const noexcept {
  // splitmix64's finaliser over the words: fixed-width integer arithmetic, the same on every host.
  std::uint64_t h = 0x9e3779b97f4a7c15ULL;
  for (std::size_t i = 0; i < words_; ++i) {
    std::uint64_t z = h ^ state[i];
    z = (z ^ (z >> 30U)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27U)) * 0x94d049bb133111ebULL;
    h = z ^ (z >> 31U);
  }
  return h;
}

StateTable::Insert StateTable::insert(std::span<const std::uint64_t> state) noexcept {
  for (std::size_t slot = hash(state) & mask_;; slot = (slot + 1) & mask_) {
    if (slot_epoch_[slot] != epoch_) {
      if (size_ == max_states_) return {};
      const auto index = static_cast<std::int32_t>(size_);
      std::copy(state.begin(), state.begin() + static_cast<std::ptrdiff_t>(words_),
                states_.begin() + static_cast<std::ptrdiff_t>(size_ * words_));
      slot_epoch_[slot] = epoch_;
      slot_index_[slot] = index;
      ++size_;
      return {index, true};
    }
    const std::int32_t index = slot_index_[slot];
    if (std::equal(state.begin(), state.begin() + static_cast<std::ptrdiff_t>(words_),
                   states_.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(index) * words_))) {
      return {index, false};
    }
  }
}

std::span<const std::uint64_t> StateTable::state(std::int32_t index) const noexcept {
  return std::span<const std::uint64_t>(states_).subspan(static_cast<std::size_t>(index) * words_, words_);
}

}  // namespace ringlet::pddl
