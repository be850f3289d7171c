#pragma once
// Shared by the whiteboard tests: all message types as a gtest type list, and a filler that sets
// every field of any message from one "profile" of awkward values, so round-trip tests need no
// per-type code either.
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "ringlet/whiteboard/binary.hpp"
#include "ringlet/whiteboard/messages.hpp"

namespace ringlet::wb::test {

template <class L>
struct ToGtest;
template <class... Ts>
struct ToGtest<TypeList<Ts...>> {
  using type = ::testing::Types<Ts...>;
};
using AllMessageTypes = ToGtest<AllMessages>::type;

inline constexpr int kProfiles = 6;

inline double double_for(int profile, std::size_t field) {
  using L = std::numeric_limits<double>;
  const std::array<double, 18> values{0.0, -0.0, 1.0 / 3.0, -2.5e-300, L::max(), L::lowest(),
                                       L::min(), L::denorm_min(), -L::denorm_min(), L::epsilon(),
                                       L::infinity(), -L::infinity(), L::quiet_NaN(),
                                       -L::quiet_NaN(), 0.1, 1e22, 123456789.123456789, -7.0};
  return values[(static_cast<std::size_t>(profile) * 5 + field * 7) % values.size()];
}

inline std::string string_for(int profile, std::size_t cap) {
  const std::array<std::string, 6> s{"", "plain", "comma,separated\\back,slash",
                                     std::string("nul\0and\x01\x7f\ttab\nnewline\r", 22),
                                     std::string(400, 'w'), " spaced , out \\x41 "};
  const std::string& v = s[static_cast<std::size_t>(profile) % s.size()];
  return v.substr(0, cap);
}

template <class I>
I int_for(int profile, std::size_t field) {
  using L = std::numeric_limits<I>;
  const std::array<I, 5> values{L::min(), L::max(), I{0}, I{1}, static_cast<I>(L::max() / 3)};
  return values[(static_cast<std::size_t>(profile) + field) % values.size()];
}

struct Filler {
  int profile;
  std::size_t field = 0;

  void set(bool& v) { v = (profile + static_cast<int>(field)) % 2 == 0; }
  void set(double& v) { v = double_for(profile, field); }
  template <std::integral I>
    requires(!std::same_as<I, bool>)
  void set(I& v) {
    v = int_for<I>(profile, field);
  }
  template <std::size_t N>
  void set(FixedString<N>& v) {
    v = string_for(profile, N);
  }
  template <SchemaEnum E>
  void set(E& v) {
    const auto& entries = EnumTraits<E>::kEntries;
    v = entries[static_cast<std::size_t>(profile) % std::size(entries)].value;
  }
  template <class V, std::size_t N>
  void set(std::array<V, N>& v) {
    for (auto& e : v) {
      set(e);
      ++field;
    }
  }
};

/// A T with every field set from `profile`.
template <class T>
T sample(int profile) {
  T msg{};
  Filler f{profile};
  visit_fields(msg, [&f](std::string_view, auto& field) {
    f.set(field);
    ++f.field;
  });
  return msg;
}

/// Bytes of the binary form: equal bytes = bit-identical messages (NaN and -0.0 included).
template <class T>
std::vector<std::byte> bytes_of(const T& msg) {
  std::vector<std::byte> out(encoded_size<T>());
  EXPECT_EQ(encode(msg, out), out.size());
  return out;
}

}  // namespace ringlet::wb::test
