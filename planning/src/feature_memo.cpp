#include "ringlet/planning/feature_memo.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <utility>

namespace ringlet::planning {

void FeatureMemo::reserve(std::size_t capacity) {
  // Three quarters full at most, so that a probe for a missing key ends soon.
  slots_.assign(std::bit_ceil(std::max<std::size_t>(capacity + capacity / 3 + 1, 8)), Slot{});
  used_ = 0;
}

std::size_t FeatureMemo::home(const Features& x) const noexcept {
  std::uint64_t h = 1469598103934665603ULL;  // FNV-1a over the bits
  for (const double v : x) {
    h ^= std::bit_cast<std::uint64_t>(v);
    h *= 1099511628211ULL;
    h ^= h >> 29;
  }
  return static_cast<std::size_t>(h) & (slots_.size() - 1);
}

bool FeatureMemo::find(const Features& x, double& value) const noexcept {
  if (slots_.empty()) return false;
  for (std::size_t i = home(x);; i = (i + 1) & (slots_.size() - 1)) {
    const Slot& s = slots_[i];
    if (!s.used) return false;
    if (s.key == x) {
      value = s.value;
      return true;
    }
  }
}

void FeatureMemo::insert(const Features& x, double value) noexcept {
  if (slots_.empty() || (used_ + 1) * 4 > slots_.size() * 3) return;
  for (std::size_t i = home(x);; i = (i + 1) & (slots_.size() - 1)) {
    Slot& s = slots_[i];
    if (s.used && s.key == x) return;
    if (!s.used) {
      s = Slot{x, value, true};
      ++used_;
      return;
    }
  }
}

void FeatureMemo::clear() noexcept {
  if (used_ == 0) return;
  for (Slot& s : slots_) s.used = false;
  used_ = 0;
}

void FeatureMemo::swap(FeatureMemo& other) noexcept {
  slots_.swap(other.slots_);
  std::swap(used_, other.used_);
}

}  // namespace ringlet::planning
