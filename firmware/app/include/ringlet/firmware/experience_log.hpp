#pragma once
// The experiences a mission records ([planner] record, learn_online): the planner task adds them
// in the cycle into room reserved at start-up ([planner] capacity), and the mission runner writes
// them to the file after the cycle has stopped.
#include <cstddef>
#include <span>
#include <vector>

#include "ringlet/planning/experience.hpp"

namespace ringlet::firmware {

class ExperienceLog {
 public:
  /// Room for `capacity` experiences (start-up).
  void reserve(std::size_t capacity) {
    experiences_.clear();
    experiences_.reserve(capacity);
    dropped_ = 0;
  }
  /// Keeps `e`; false (counted as dropped) when full. Never allocates.
  bool add(const planning::Experience& e) noexcept {
    if (experiences_.size() == experiences_.capacity()) {
      ++dropped_;
      return false;
    }
    experiences_.push_back(e);  // within the reserved capacity: no allocation
    return true;
  }
  [[nodiscard]] std::span<const planning::Experience> experiences() const noexcept { return experiences_; }
  [[nodiscard]] std::size_t dropped() const noexcept { return dropped_; }

 private:
  std::vector<planning::Experience> experiences_;
  std::size_t dropped_ = 0;
};

}  // namespace ringlet::firmware
