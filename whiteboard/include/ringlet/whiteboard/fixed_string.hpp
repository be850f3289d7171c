#pragma once
// A string that lives inside a message: N chars in place plus a length, so a message holding one
// stays trivially copyable and posting it never touches the heap. Assignment truncates.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace ringlet::wb {

template <std::size_t N>
class FixedString {
  static_assert(N > 0 && N <= 0xFFFF, "the wire format stores the length in 16 bits");

 public:
  static constexpr std::size_t kCapacity = N;

  constexpr FixedString() noexcept = default;
  // Implicit on purpose: `status.state = "Loop";` reads like the std::string it replaces.
  constexpr FixedString(std::string_view s) noexcept { assign(s); }  // NOLINT(google-explicit-constructor)
  constexpr FixedString(const char* s) noexcept : FixedString(std::string_view{s}) {}  // NOLINT

  constexpr FixedString& operator=(std::string_view s) noexcept {
    assign(s);
    return *this;
  }
  constexpr FixedString& operator=(const char* s) noexcept {  // else "x" is ambiguous
    assign(s);
    return *this;
  }

  /// Copies at most N chars of `s`; returns false if it had to truncate.
  constexpr bool assign(std::string_view s) noexcept {
    const std::size_t n = std::min(s.size(), N);
    std::copy_n(s.data(), n, data_.begin());
    // Zero the tail so equal strings are equal bytes (binary encoding, memcmp in tests).
    std::fill(data_.begin() + static_cast<std::ptrdiff_t>(n), data_.end(), '\0');
    size_ = static_cast<std::uint16_t>(n);
    return n == s.size();
  }

  [[nodiscard]] constexpr std::string_view view() const noexcept { return {data_.data(), size_}; }
  [[nodiscard]] constexpr std::size_t size() const noexcept { return size_; }
  [[nodiscard]] constexpr bool empty() const noexcept { return size_ == 0; }
  [[nodiscard]] constexpr const char* data() const noexcept { return data_.data(); }

  friend constexpr bool operator==(const FixedString& a, const FixedString& b) noexcept {
    return a.view() == b.view();
  }
  friend constexpr bool operator==(const FixedString& a, std::string_view b) noexcept {
    return a.view() == b;
  }
  friend constexpr bool operator==(const FixedString& a, const char* b) noexcept {
    return a.view() == std::string_view{b};
  }

 private:
  std::array<char, N> data_{};
  std::uint16_t size_ = 0;
};

}  // namespace ringlet::wb
