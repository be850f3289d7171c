#pragma once
// Predictions memoized by feature vector: most transitions of a map share their features (every
// step through empty space has the same eleven numbers), so a kNN query per distinct vector is
// enough. A fixed-capacity open-addressing table sized at start-up: a lookup or an insertion
// never allocates, and a full table (three quarters used) just stops remembering. Keys compare
// bit for bit, so a hit returns exactly what the query it stands for returned.
#include <cstddef>
#include <vector>

#include "ringlet/planning/experience.hpp"

namespace ringlet::planning {

class FeatureMemo {
 public:
  /// Room for at least `capacity` vectors (allocates: start-up); forgets everything.
  void reserve(std::size_t capacity);
  /// The remembered value for `x`, if any.
  [[nodiscard]] bool find(const Features& x, double& value) const noexcept;
  /// Remembers `value` for `x` unless the table is full (or `x` is there already).
  void insert(const Features& x, double value) noexcept;
  void clear() noexcept;
  [[nodiscard]] std::size_t size() const noexcept { return used_; }
  void swap(FeatureMemo& other) noexcept;

 private:
  struct Slot {
    Features key{};
    double value = 0.0;
    bool used = false;
  };
  [[nodiscard]] std::size_t home(const Features& x) const noexcept;

  std::vector<Slot> slots_;  // a power of two
  std::size_t used_ = 0;
};

}  // namespace ringlet::planning
