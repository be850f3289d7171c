#include "ringlet/pddl/arena.hpp"

#include <algorithm>
#include <limits>

namespace ringlet::pddl {

Arena::Arena(std::size_t bytes) : memory_(new std::byte[bytes == 0 ? 1 : bytes]), capacity_(bytes) {}

void Arena::reset() noexcept {
  used_ = 0;
  overflow_.clear();
}

void* Arena::raw(std::size_t n, std::size_t size, std::size_t align, const char* what) {
  const auto base = reinterpret_cast<std::uintptr_t>(memory_.get());
  std::size_t start = used_;
  const std::size_t misalign = (base + start) % align;
  if (misalign != 0) start += align - misalign;
  const bool too_many = size != 0 && n > std::numeric_limits<std::size_t>::max() / size;
  if (overflowed() || too_many || start > capacity_ || n * size > capacity_ - start) {
    if (!overflowed()) {
      overflow_ = "the arena of " + std::to_string(capacity_) + " bytes cannot hold " + what + " (" +
                  std::to_string(n) + " x " + std::to_string(size) + " bytes, " +
                  std::to_string(capacity_ - std::min(used_, capacity_)) + " bytes left)";
    }
    return nullptr;
  }
  used_ = start + n * size;
  return memory_.get() + start;
}

}  // namespace ringlet::pddl
