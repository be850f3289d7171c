#include "ringlet/pddl/open_list.hpp"

#include <utility>

namespace ringlet::pddl {

bool OpenList::push(std::int64_t key, std::int32_t node, std::int32_t g) noexcept {
  if (size_ == heap_.size()) return false;
  std::size_t i = size_++;
  heap_[i] = {key, next_order_++, node, g};
  while (i > 0 && before(heap_[i], heap_[(i - 1) / 2])) {
    std::swap(heap_[i], heap_[(i - 1) / 2]);
    i = (i - 1) / 2;
  }
  return true;
}

OpenEntry OpenList::pop() noexcept {
  const OpenEntry top = heap_[0];
  heap_[0] = heap_[--size_];
  for (std::size_t i = 0;;) {
    const std::size_t l = 2 * i + 1;
    const std::size_t r = l + 1;
    std::size_t m = i;
    if (l < size_ && before(heap_[l], heap_[m])) m = l;
    if (r < size_ && before(heap_[r], heap_[m])) m = r;
    if (m == i) break;
    std::swap(heap_[i], heap_[m]);
    i = m;
  }
  return top;
}

}  // namespace ringlet::pddl
