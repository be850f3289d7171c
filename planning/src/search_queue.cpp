#include "ringlet/planning/search_queue.hpp"

namespace ringlet::planning {

void SearchQueue::reserve(int vertices) {
  heap_.clear();
  heap_.reserve(static_cast<std::size_t>(vertices));
  pos_.assign(static_cast<std::size_t>(vertices), -1);
}

void SearchQueue::clear() noexcept {
  for (const Entry& e : heap_) pos_[static_cast<std::size_t>(e.vertex)] = -1;
  heap_.clear();
}

void SearchQueue::place(std::size_t i, const Entry& e) noexcept {
  heap_[i] = e;
  pos_[static_cast<std::size_t>(e.vertex)] = static_cast<std::int32_t>(i);
}

void SearchQueue::sift_up(std::size_t i) noexcept {
  const Entry e = heap_[i];
  while (i > 0) {
    const std::size_t parent = (i - 1) / 2;
    if (!before(e, heap_[parent])) break;
    place(i, heap_[parent]);
    i = parent;
  }
  place(i, e);
}

void SearchQueue::sift_down(std::size_t i) noexcept {
  const Entry e = heap_[i];
  const std::size_t n = heap_.size();
  for (;;) {
    std::size_t child = 2 * i + 1;
    if (child >= n) break;
    if (child + 1 < n && before(heap_[child + 1], heap_[child])) ++child;
    if (!before(heap_[child], e)) break;
    place(i, heap_[child]);
    i = child;
  }
  place(i, e);
}

void SearchQueue::push_or_update(int v, const SearchKey& key) noexcept {
  const std::int32_t at = pos_[static_cast<std::size_t>(v)];
  if (at < 0) {
    heap_.push_back({key, v});  // within the reserved capacity: one entry per vertex at most
    sift_up(heap_.size() - 1);
    return;
  }
  const auto i = static_cast<std::size_t>(at);
  const SearchKey old = heap_[i].key;
  heap_[i].key = key;
  if (key < old) {
    sift_up(i);
  } else {
    sift_down(i);
  }
}

void SearchQueue::remove(int v) noexcept {
  const std::int32_t at = pos_[static_cast<std::size_t>(v)];
  if (at < 0) return;
  const auto i = static_cast<std::size_t>(at);
  pos_[static_cast<std::size_t>(v)] = -1;
  const Entry last = heap_.back();
  heap_.pop_back();
  if (i == heap_.size()) return;
  place(i, last);
  sift_up(i);
  sift_down(static_cast<std::size_t>(pos_[static_cast<std::size_t>(last.vertex)]));
}

int SearchQueue::pop() noexcept {
  const int v = heap_.front().vertex;
  remove(v);
  return v;
}

}  // namespace ringlet::planning
