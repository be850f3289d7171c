#pragma once
// A fixed byte budget, allocated once at construction (start-up), that the grounded task is built
// into. Running out is a status naming what did not fit, never an exception: the service thread
// reports it and the cycle keeps the task it had.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <type_traits>

namespace ringlet::pddl {

class Arena {
 public:
  explicit Arena(std::size_t bytes);

  /// Room for n values of T (value-initialised), or an empty span when the budget is exceeded;
  /// then overflowed() is true and overflow() names `what` and the sizes.
  template <typename T>
  [[nodiscard]] std::span<T> allocate(std::size_t n, const char* what) {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                  "the arena never runs destructors");
    void* p = raw(n, sizeof(T), alignof(T), what);
    if (p == nullptr) return {};
    T* first = static_cast<T*>(p);
    for (std::size_t i = 0; i < n; ++i) new (first + i) T{};
    return {first, n};
  }

  /// Forgets everything allocated (the memory stays): the next task is built from the start.
  void reset() noexcept;

  [[nodiscard]] std::size_t capacity() const noexcept { return capacity_; }
  [[nodiscard]] std::size_t used() const noexcept { return used_; }
  [[nodiscard]] bool overflowed() const noexcept { return !overflow_.empty(); }
  /// "the arena of 4096 bytes cannot hold operators (120 x 64 bytes, 900 bytes left)".
  [[nodiscard]] const std::string& overflow() const noexcept { return overflow_; }

 private:
  void* raw(std::size_t n, std::size_t size, std::size_t align, const char* what);

  std::unique_ptr<std::byte[]> memory_;
  std::size_t capacity_;
  std::size_t used_ = 0;
  std::string overflow_;
};

}  // namespace ringlet::pddl
