#pragma once
// How one field of each supported type is written and read, in text and in binary. The schema
// decides which fields a message has; this file decides what a field looks like. Adding a message
// type never touches this file; adding a new *kind* of field does.
//
// Text: fields are separated by ','. Doubles use the shortest form that round-trips exactly
// (std::to_chars), plus "inf", "-inf", "nan", "-0". Bools are "true"/"false" ("1"/"0" accepted).
// Strings are written as-is except '\' -> "\\", ',' -> "\,", and control chars -> "\n", "\t",
// "\r" or "\xHH". Arrays are their elements, comma separated. Enums are their schema text.
//
// Binary: little-endian whatever the host. bool: 1 byte (0/1); integers: their width; double: the
// IEEE-754 bits as a u64; enums: their underlying integer; FixedString<N>: u16 length + N bytes
// (zero padded, so equal strings encode identically); arrays: their elements in order.
#include <array>
#include <bit>
#include <charconv>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

#include "ringlet/whiteboard/fixed_string.hpp"

namespace ringlet::wb {

static_assert(std::numeric_limits<double>::is_iec559, "the binary form carries IEEE-754 doubles");

/// Specialised for every schema enum (from schema.def, in messages.hpp).
template <class E>
struct EnumTraits;

template <class E>
struct EnumEntry {
  E value;
  std::string_view text;
};

template <class E>
concept SchemaEnum = std::is_enum_v<E> && requires { EnumTraits<E>::kEntries; };

namespace detail {

// ---- text -----------------------------------------------------------------------------------------

enum class TextError : std::uint8_t {
  kNone, kNotANumber, kOutOfRange, kNotABool, kTooLong, kBadEscape, kUnknownValue
};
std::string_view describe(TextError e) noexcept;

/// Splits a message's text at commas not escaped by '\'. Never allocates.
class Tokens {
 public:
  explicit Tokens(std::string_view text) noexcept : rest_(text) {}
  /// The next token, or false when the text is used up.
  bool next(std::string_view& token) noexcept;
  [[nodiscard]] bool done() const noexcept { return done_; }

 private:
  std::string_view rest_;
  bool done_ = false;
};

void append_text(std::string& out, bool v);
void append_text(std::string& out, double v);
void append_escaped(std::string& out, std::string_view s);

template <std::integral I>
  requires(!std::same_as<I, bool>)
void append_text(std::string& out, I v) {
  std::array<char, 24> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  out.append(buf.data(), r.ptr);
}

template <std::size_t N>
void append_text(std::string& out, const FixedString<N>& v) {
  append_escaped(out, v.view());
}

template <SchemaEnum E>
void append_text(std::string& out, E v) {
  for (const auto& e : EnumTraits<E>::kEntries) {
    if (e.value == v) {
      out.append(e.text);
      return;
    }
  }
  // A value outside the schema (cast in by hand): keep it visible and parseable.
  append_text(out, static_cast<std::underlying_type_t<E>>(v));
}

template <class V, std::size_t N>
void append_text(std::string& out, const std::array<V, N>& v) {
  for (std::size_t i = 0; i < N; ++i) {
    if (i != 0) out.push_back(',');
    append_text(out, v[i]);
  }
}

/// Parse one token into `v`. On error `v` may be partly written (callers parse into a copy).
TextError parse_token(std::string_view token, bool& v) noexcept;
TextError parse_token(std::string_view token, double& v) noexcept;
/// Undoes append_escaped into `out` (capacity `cap`); sets `size`.
TextError unescape(std::string_view token, char* out, std::size_t cap, std::size_t& size) noexcept;
std::string_view trim(std::string_view s) noexcept;

template <std::integral I>
  requires(!std::same_as<I, bool>)
TextError parse_token(std::string_view token, I& v) noexcept {
  token = trim(token);
  const char* end = token.data() + token.size();
  const auto r = std::from_chars(token.data(), end, v);
  if (r.ec == std::errc::result_out_of_range) return TextError::kOutOfRange;
  if (r.ec != std::errc{} || r.ptr != end || token.empty()) return TextError::kNotANumber;
  return TextError::kNone;
}

template <std::size_t N>
TextError parse_token(std::string_view token, FixedString<N>& v) noexcept {
  std::array<char, N> buf{};
  std::size_t size = 0;
  const TextError e = unescape(token, buf.data(), N, size);
  if (e == TextError::kNone) v.assign(std::string_view{buf.data(), size});
  return e;
}

template <SchemaEnum E>
TextError parse_token(std::string_view token, E& v) noexcept {
  token = trim(token);
  for (const auto& e : EnumTraits<E>::kEntries) {
    if (e.text == token) {
      v = e.value;
      return TextError::kNone;
    }
  }
  return TextError::kUnknownValue;
}

// ---- binary ---------------------------------------------------------------------------------------

template <class V>
struct Wire;  // kSize, write(p, v), read(p, v) -> false if the bytes are not a valid V

template <std::unsigned_integral U>
constexpr void put_le(std::byte* p, U v) noexcept {
  for (std::size_t i = 0; i < sizeof(U); ++i) {
    p[i] = static_cast<std::byte>(static_cast<std::uint64_t>(v) >> (8 * i) & 0xFFU);
  }
}
template <std::unsigned_integral U>
constexpr U get_le(const std::byte* p) noexcept {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < sizeof(U); ++i) {
    v |= static_cast<std::uint64_t>(std::to_integer<std::uint8_t>(p[i])) << (8 * i);
  }
  return static_cast<U>(v);
}

template <>
struct Wire<bool> {
  static constexpr std::size_t kSize = 1;
  static void write(std::byte* p, bool v) noexcept { p[0] = std::byte{v ? std::uint8_t{1} : std::uint8_t{0}}; }
  static bool read(const std::byte* p, bool& v) noexcept {
    const auto b = std::to_integer<std::uint8_t>(p[0]);
    v = b == 1;
    return b <= 1;
  }
};

template <std::integral I>
  requires(!std::same_as<I, bool>)
struct Wire<I> {
  using U = std::make_unsigned_t<I>;
  static constexpr std::size_t kSize = sizeof(I);
  static void write(std::byte* p, I v) noexcept { put_le(p, static_cast<U>(v)); }
  static bool read(const std::byte* p, I& v) noexcept {
    v = static_cast<I>(get_le<U>(p));
    return true;
  }
};

template <>
struct Wire<double> {
  static constexpr std::size_t kSize = 8;
  static void write(std::byte* p, double v) noexcept { put_le(p, std::bit_cast<std::uint64_t>(v)); }
  static bool read(const std::byte* p, double& v) noexcept {
    v = std::bit_cast<double>(get_le<std::uint64_t>(p));
    return true;
  }
};

template <SchemaEnum E>
struct Wire<E> {
  using U = std::make_unsigned_t<std::underlying_type_t<E>>;
  static constexpr std::size_t kSize = sizeof(U);
  static void write(std::byte* p, E v) noexcept { put_le(p, static_cast<U>(v)); }
  static bool read(const std::byte* p, E& v) noexcept {
    const U raw = get_le<U>(p);
    for (const auto& e : EnumTraits<E>::kEntries) {
      if (static_cast<U>(e.value) == raw) {
        v = e.value;
        return true;
      }
    }
    return false;
  }
};

template <std::size_t N>
struct Wire<FixedString<N>> {
  static constexpr std::size_t kSize = 2 + N;
  static void write(std::byte* p, const FixedString<N>& v) noexcept {
    put_le(p, static_cast<std::uint16_t>(v.size()));
    for (std::size_t i = 0; i < N; ++i) {
      p[2 + i] = i < v.size() ? static_cast<std::byte>(v.data()[i]) : std::byte{0};
    }
  }
  static bool read(const std::byte* p, FixedString<N>& v) noexcept {
    const std::size_t size = get_le<std::uint16_t>(p);
    if (size > N) return false;
    std::array<char, N> buf{};
    for (std::size_t i = 0; i < size; ++i) buf[i] = static_cast<char>(p[2 + i]);
    v.assign(std::string_view{buf.data(), size});
    return true;
  }
};

template <class V, std::size_t N>
struct Wire<std::array<V, N>> {
  static constexpr std::size_t kSize = N * Wire<V>::kSize;
  static void write(std::byte* p, const std::array<V, N>& v) noexcept {
    for (std::size_t i = 0; i < N; ++i) Wire<V>::write(p + i * Wire<V>::kSize, v[i]);
  }
  static bool read(const std::byte* p, std::array<V, N>& v) noexcept {
    for (std::size_t i = 0; i < N; ++i) {
      if (!Wire<V>::read(p + i * Wire<V>::kSize, v[i])) return false;
    }
    return true;
  }
};

}  // namespace detail
}  // namespace ringlet::wb
