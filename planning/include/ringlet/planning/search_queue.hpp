#pragma once
// The priority queue of D* Lite and A*: a binary min-heap over vertex ids with decrease/increase
// key and removal, all storage sized once (reserve), so nothing allocates while searching. Ties
// between equal keys go to the lower vertex id: the order of expansions, and so the plan, is the
// same on every host.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ringlet/planning/grid_graph.hpp"

namespace ringlet::planning {

/// D* Lite's two-part key [min(g, rhs) + h + km; min(g, rhs)] (A* uses [f; g]), compared
/// lexicographically.
struct SearchKey {
  Cost k1 = 0;
  Cost k2 = 0;
  friend bool operator<(const SearchKey& a, const SearchKey& b) noexcept {
    return a.k1 < b.k1 || (a.k1 == b.k1 && a.k2 < b.k2);
  }
  friend bool operator==(const SearchKey&, const SearchKey&) = default;
};

class SearchQueue {
 public:
  /// Sizes the queue for vertex ids 0 .. vertices − 1 (allocates: start-up only) and empties it.
  void reserve(int vertices);
  /// Empties the queue in O(size).
  void clear() noexcept;

  [[nodiscard]] bool empty() const noexcept { return heap_.empty(); }
  [[nodiscard]] std::size_t size() const noexcept { return heap_.size(); }
  [[nodiscard]] bool contains(int v) const noexcept { return pos_[static_cast<std::size_t>(v)] >= 0; }
  [[nodiscard]] int top() const noexcept { return heap_.front().vertex; }
  [[nodiscard]] SearchKey top_key() const noexcept { return heap_.front().key; }

  /// Inserts `v` or changes its key.
  void push_or_update(int v, const SearchKey& key) noexcept;
  /// Removes `v` if it is queued.
  void remove(int v) noexcept;
  /// Removes and returns the top vertex.
  int pop() noexcept;

 private:
  struct Entry {
    SearchKey key;
    int vertex;
  };
  [[nodiscard]] static bool before(const Entry& a, const Entry& b) noexcept {
    return a.key < b.key || (a.key == b.key && a.vertex < b.vertex);
  }
  void place(std::size_t i, const Entry& e) noexcept;
  void sift_up(std::size_t i) noexcept;
  void sift_down(std::size_t i) noexcept;

  std::vector<Entry> heap_;            // capacity reserved; push_back never reallocates
  std::vector<std::int32_t> pos_;      // heap index of each vertex, −1 when not queued
};

}  // namespace ringlet::planning
