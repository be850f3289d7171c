#pragma once
// Counting heap allocations, for the tests that prove a path allocates nothing. Linking
// ringlet_test_allocation_counter into a test executable counts, in every thread, every operator
// new (all forms, aligned too) and every C allocation function (malloc, calloc, realloc,
// posix_memalign, aligned_alloc, memalign, valloc, pvalloc), whoever calls them: the code under
// test, libstdc++, OpenCV, glibc. Plain builds replace those functions in the executable;
// AddressSanitizer and ThreadSanitizer builds count through the sanitizer's allocation hook
// (see allocation_counter.cpp).
#include <cstdint>

namespace ringlet::test {

/// Allocations since the program started, all threads.
[[nodiscard]] std::uint64_t allocations() noexcept;

/// Allocations made by the calling thread since it started: for a path that must not allocate
/// while other threads do so by design (a model rebuilt off the cycle).
[[nodiscard]] std::uint64_t thread_allocations() noexcept;

/// Allocations made while it lives.
class AllocationCounter {
 public:
  AllocationCounter() noexcept : start_(allocations()) {}
  [[nodiscard]] std::uint64_t count() const noexcept { return allocations() - start_; }

 private:
  std::uint64_t start_;
};

/// Allocations made by the constructing thread while it lives (read it on that thread).
class ThreadAllocationCounter {
 public:
  ThreadAllocationCounter() noexcept : start_(thread_allocations()) {}
  [[nodiscard]] std::uint64_t count() const noexcept { return thread_allocations() - start_; }

 private:
  std::uint64_t start_;
};

}  // namespace ringlet::test
