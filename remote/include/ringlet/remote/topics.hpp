#pragma once
// The whiteboard's message types as DDS topics. idlc turned the IDL that remote/idl/wb_idl.py wrote
// from schema.def into C structs (ringlet_wb.h); here, X-macros over the same schema.def give, for
// every message type T:
//   DdsType<T>::Sample      the C struct (ringlet_msg_dds__<T>_), DdsType<T>::descriptor()
//   to_sample(msg, robot, generation, sample)      whiteboard -> DDS (never fails)
//   from_sample(sample, msg)                       DDS -> whiteboard, validated: false when a value
//                                                   has no whiteboard meaning (an enum value outside
//                                                   the schema's, a string without its terminator,
//                                                   a NaN or infinite double); msg is then untouched
// and topic_name(T::kName) = "rt/ringlet/<snake_case name>" (ROS 2's topic naming: ROS 2 tools on
// the network list the topic as /ringlet/<snake_case name>). Nothing is written per type.
#include <dds/dds.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

#include "ringlet/whiteboard/messages.hpp"
#include "ringlet_wb.h"

namespace ringlet::remote {

template <class T>
struct DdsType;

#define WB_MESSAGE_BEGIN(Name, Id, Version)                                          \
  template <>                                                                        \
  struct DdsType<wb::Name> {                                                         \
    using Sample = ::ringlet_msg_dds__##Name##_;                                     \
    static const dds_topic_descriptor_t* descriptor() noexcept {                     \
      return &::ringlet_msg_dds__##Name##__desc;                                     \
    }                                                                                \
  };
#include "ringlet/whiteboard/schema.def"

/// "rt/ringlet/fsm_status" for "FsmStatus".
[[nodiscard]] std::string topic_name(std::string_view type_name);
/// "rt/ringlet/request/fsm_control" for "FsmControl": where monitors write requests to robots
/// (the sample's robot field names the robot asked).
[[nodiscard]] std::string request_topic_name(std::string_view type_name);

namespace detail {

// ---- whiteboard -> DDS --------------------------------------------------------------------------
template <class S>
  requires std::is_arithmetic_v<S>
void put(const S& v, S& d) noexcept {
  d = v;
}
template <wb::SchemaEnum E, class C>
  requires std::is_enum_v<C>
void put(const E& v, C& d) noexcept {
  d = static_cast<C>(static_cast<std::underlying_type_t<E>>(v));
}
template <std::size_t N>
void put(const wb::FixedString<N>& v, char (&d)[N + 1]) noexcept {
  const std::string_view s = v.view();
  std::memcpy(d, s.data(), s.size());
  std::memset(d + s.size(), 0, N + 1 - s.size());
}
template <class T, std::size_t N, class U>
void put(const std::array<T, N>& v, U (&d)[N]) noexcept {
  for (std::size_t i = 0; i < N; ++i) put(v[i], d[i]);
}

// ---- DDS -> whiteboard (validated) --------------------------------------------------------------
template <class S>
  requires std::is_integral_v<S>
bool get(const S& s, S& d) noexcept {
  d = s;
  return true;
}
inline bool get(const double& s, double& d) noexcept {
  d = s;
  return std::isfinite(s);
}
template <wb::SchemaEnum E, class C>
  requires std::is_enum_v<C>
bool get(const C& s, E& d) noexcept {
  // The bits as an integer: a value outside the C enum's enumerators may arrive from the network,
  // and reading it as the enum type would already be undefined behaviour in C++.
  std::underlying_type_t<C> bits{};
  static_assert(sizeof bits == sizeof s);
  std::memcpy(&bits, &s, sizeof bits);
  const auto raw = static_cast<long long>(bits);
  for (const auto& e : wb::EnumTraits<E>::kEntries) {
    if (static_cast<long long>(e.value) == raw) {
      d = e.value;
      return true;
    }
  }
  return false;
}
template <std::size_t N>
bool get(const char (&s)[N + 1], wb::FixedString<N>& d) noexcept {
  const void* end = std::memchr(s, '\0', N + 1);
  if (end == nullptr) return false;
  d.assign(std::string_view{s, static_cast<std::size_t>(static_cast<const char*>(end) - s)});
  return true;
}
template <class T, std::size_t N, class U>
bool get(const U (&s)[N], std::array<T, N>& d) noexcept {
  bool ok = true;
  for (std::size_t i = 0; i < N; ++i) ok = get(s[i], d[i]) && ok;
  return ok;
}

}  // namespace detail

#define WB_MESSAGE_BEGIN(Name, Id, Version)                                                      \
  inline void to_sample(const wb::Name& m, std::uint16_t robot, std::uint64_t generation,       \
                        DdsType<wb::Name>::Sample& s) noexcept {                                 \
    s.robot = robot;                                                                             \
    s.generation = generation;
#define WB_FIELD(FieldName, ...) detail::put(m.FieldName, s.FieldName);
#define WB_MESSAGE_END(Name) }
#include "ringlet/whiteboard/schema.def"

#define WB_MESSAGE_BEGIN(Name, Id, Version)                                                       \
  [[nodiscard]] inline bool from_sample(const DdsType<wb::Name>::Sample& s, wb::Name& out) noexcept { \
    wb::Name m{};                                                                                 \
    bool ok = true;
#define WB_FIELD(FieldName, ...) ok = detail::get(s.FieldName, m.FieldName) && ok;
#define WB_MESSAGE_END(Name) \
  if (ok) out = m;           \
  return ok;                 \
  }
#include "ringlet/whiteboard/schema.def"

}  // namespace ringlet::remote
