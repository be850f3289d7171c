#pragma once
// The binary form of any message, ready for the network: an 8-byte header then the fields in
// schema order, all little-endian whatever the host (see field_codec.hpp for each field):
//
//   u16 type id | u16 schema version | u32 payload size | payload (fixed size per type)
//
// encode never allocates; decode refuses a wrong id, version or size, a short buffer, and bytes
// that are not a valid value (a bool other than 0/1, a string longer than its capacity, an enum
// value the schema does not know).
#include <cstddef>
#include <cstdint>
#include <span>

#include "ringlet/whiteboard/field_codec.hpp"
#include "ringlet/whiteboard/messages.hpp"
#include "ringlet/whiteboard/result.hpp"

namespace ringlet::wb {

struct WireHeader {
  TypeId id;
  std::uint16_t version;
  std::uint32_t payload_size;
};
inline constexpr std::size_t kWireHeaderSize = 8;

/// Payload bytes of T (fixed per type and schema version).
template <Message T>
constexpr std::size_t payload_size() noexcept {
  std::size_t n = 0;
  const T probe{};
  visit_fields(probe, [&n](std::string_view, const auto& field) {
    n += detail::Wire<std::remove_cvref_t<decltype(field)>>::kSize;
  });
  return n;
}

/// Header + payload bytes of T.
template <Message T>
constexpr std::size_t encoded_size() noexcept {
  return kWireHeaderSize + payload_size<T>();
}

/// Writes msg into out; returns the bytes written, or 0 if out is shorter than encoded_size<T>().
template <Message T>
std::size_t encode(const T& msg, std::span<std::byte> out) noexcept {
  constexpr std::size_t kSize = encoded_size<T>();
  if (out.size() < kSize) return 0;
  std::byte* p = out.data();
  detail::put_le(p, to_underlying(T::kId));
  detail::put_le(p + 2, T::kVersion);
  detail::put_le(p + 4, static_cast<std::uint32_t>(payload_size<T>()));
  p += kWireHeaderSize;
  visit_fields(msg, [&p](std::string_view, const auto& field) {
    using W = detail::Wire<std::remove_cvref_t<decltype(field)>>;
    W::write(p, field);
    p += W::kSize;
  });
  return kSize;
}

/// Reads the header (to route a datagram to the right decode<T>).
Result<WireHeader> peek_header(std::span<const std::byte> in);

namespace detail {
Error wire_error(std::string_view type, std::string_view what);
Error wire_field_error(std::string_view type, std::string_view field);
Status check_header(std::span<const std::byte> in, TypeId id, std::string_view name,
                    std::uint16_t version, std::size_t payload);
}  // namespace detail

/// Decodes exactly one T from the start of in (trailing bytes are ignored).
template <Message T>
Result<T> decode(std::span<const std::byte> in) {
  if (Status s = detail::check_header(in, T::kId, T::kName, T::kVersion, payload_size<T>()); !s) {
    return Error{s.error()};
  }
  T out{};
  const std::byte* p = in.data() + kWireHeaderSize;
  std::string_view bad;
  visit_fields(out, [&](std::string_view name, auto& field) {
    using W = detail::Wire<std::remove_cvref_t<decltype(field)>>;
    if (bad.empty() && !W::read(p, field)) bad = name;
    p += W::kSize;
  });
  if (!bad.empty()) return detail::wire_field_error(T::kName, bad);
  return out;
}

}  // namespace ringlet::wb
