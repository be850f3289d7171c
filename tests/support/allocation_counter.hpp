#pragma once
// Counting heap allocations, for the tests that prove a path allocates nothing. Linking
// ringlet_test_allocation_counter replaces the global operator new/delete (every form, aligned
// too) in that test executable with versions that count, in every thread.
#include <cstdint>

namespace ringlet::test {

/// Allocations (operator new calls) since the program started, all threads.
[[nodiscard]] std::uint64_t allocations() noexcept;

/// Allocations made while it lives.
class AllocationCounter {
 public:
  AllocationCounter() noexcept : start_(allocations()) {}
  [[nodiscard]] std::uint64_t count() const noexcept { return allocations() - start_; }

 private:
  std::uint64_t start_;
};

}  // namespace ringlet::test
