#pragma once
// The message types, generated from schema.def: enums, structs (with kId, kName, kVersion,
// description(), from_string()), the field visitor the codecs walk, and the compile-time type
// list (kTypes, AllMessages, for_each_type). Nothing here is written per message type.
#include <algorithm>
#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

#include "ringlet/whiteboard/field_codec.hpp"
#include "ringlet/whiteboard/fixed_string.hpp"
#include "ringlet/whiteboard/result.hpp"

namespace ringlet::wb {

/// Stable message type id: never reused, carried in the binary header.
enum class TypeId : std::uint16_t {};
constexpr std::uint16_t to_underlying(TypeId id) noexcept { return static_cast<std::uint16_t>(id); }

// ---- enums (unscoped on purpose: `wb::kSuspend` and `wb::FsmCommand::kSuspend` both work) ------

#define WB_ENUM_BEGIN(Name, Underlying) enum Name : Underlying {
#define WB_ENUMERATOR(Name, Enumerator, Text) Enumerator,
#define WB_ENUM_END(Name) \
  }                       \
  ;
#include "ringlet/whiteboard/schema.def"

#define WB_ENUM_BEGIN(Name, Underlying) \
  template <>                           \
  struct EnumTraits<Name> {             \
    static constexpr EnumEntry<Name> kEntries[] = {
#define WB_ENUMERATOR(Name, Enumerator, Text) {Enumerator, Text},
#define WB_ENUM_END(Name) \
  }                       \
  ;                       \
  }                       \
  ;
#include "ringlet/whiteboard/schema.def"

// ---- message structs ----------------------------------------------------------------------------

#define WB_MESSAGE_BEGIN(Name, Id, Version)                  \
  struct Name {                                              \
    static constexpr TypeId kId{Id};                         \
    static constexpr std::string_view kName{#Name};          \
    static constexpr std::uint16_t kVersion{Version};
#define WB_FIELD(FieldName, ...) __VA_ARGS__ FieldName{};
#define WB_MESSAGE_END(Name)                                               \
  /** Readable comma-separated fields; from_string(description()) == *this. */ \
  [[nodiscard]] std::string description() const;                          \
  /** Parses description()'s form; the error names the field. */         \
  [[nodiscard]] static Result<Name> from_string(std::string_view text);   \
  friend bool operator==(const Name&, const Name&) = default;              \
  }                                                                        \
  ;
#include "ringlet/whiteboard/schema.def"

// visit_fields(msg, f) calls f("field", msg.field) for each field in schema order. Found by ADL.
#define WB_MESSAGE_BEGIN(Name, Id, Version)                 \
  template <class M, class F>                               \
    requires std::same_as<std::remove_const_t<M>, Name>     \
  constexpr void visit_fields(M& m, F&& f) {
#define WB_FIELD(FieldName, ...) f(std::string_view{#FieldName}, m.FieldName);
#define WB_MESSAGE_END(Name) }
#include "ringlet/whiteboard/schema.def"

// Mi-Pal's `Print_t print; print.set(...)` spelling: Name_t is the typed handle of Name.
template <class T>
class Handle;
#define WB_MESSAGE_BEGIN(Name, Id, Version) using Name##_t = Handle<Name>;
#include "ringlet/whiteboard/schema.def"

// ---- the type list ------------------------------------------------------------------------------

struct TypeInfo {
  TypeId id;
  std::string_view name;
  std::uint16_t version;
};

/// Every message type in id order (like guwhiteboardtypelist_generated.h).
inline constexpr auto kTypes = std::to_array<TypeInfo>({
#define WB_MESSAGE_BEGIN(Name, Id, Version) {TypeId{Id}, #Name, Version},
#include "ringlet/whiteboard/schema.def"
});
inline constexpr std::size_t kTypeCount = kTypes.size();

static_assert(std::is_sorted(kTypes.begin(), kTypes.end(),
                             [](const TypeInfo& a, const TypeInfo& b) { return a.id < b.id; }) &&
                  std::adjacent_find(kTypes.begin(), kTypes.end(),
                                     [](const TypeInfo& a, const TypeInfo& b) {
                                       return a.id == b.id;
                                     }) == kTypes.end(),
              "schema.def: message ids must be unique and ascending (dispatch order is id order)");

template <class... Ts>
struct TypeList {};

namespace detail {
struct ListHead {};
template <class L>
struct DropHead;
template <class... Ts>
struct DropHead<TypeList<ListHead, Ts...>> {
  using type = TypeList<Ts...>;
};
// The leading ListHead lets every schema entry expand to ", Name" (no trailing-comma problem).
using RawList = TypeList<ListHead
#define WB_MESSAGE_BEGIN(Name, Id, Version) , Name
#include "ringlet/whiteboard/schema.def"
                         >;
}  // namespace detail

/// The message types as a type list, in id order.
using AllMessages = detail::DropHead<detail::RawList>::type;

namespace detail {
template <class T, class L>
struct IndexOf;
template <class T, class... Ts>
struct IndexOf<T, TypeList<Ts...>> {
  static constexpr std::size_t value = [] {
    constexpr std::array<bool, sizeof...(Ts)> hit{std::is_same_v<T, Ts>...};
    return static_cast<std::size_t>(std::find(hit.begin(), hit.end(), true) - hit.begin());
  }();
};
template <class F, class... Ts>
constexpr void for_each_in(TypeList<Ts...>, F&& f) {
  (f(std::type_identity<Ts>{}), ...);
}
}  // namespace detail

/// A schema message type.
template <class T>
concept Message = detail::IndexOf<T, AllMessages>::value < kTypeCount;

/// Position of T in AllMessages / kTypes.
template <Message T>
inline constexpr std::size_t kIndexOf = detail::IndexOf<T, AllMessages>::value;

/// Calls f(std::type_identity<T>{}) for every message type, in id order.
template <class F>
constexpr void for_each_type(F&& f) {
  detail::for_each_in(AllMessages{}, f);
}

/// The type with this name, if any.
constexpr std::optional<TypeInfo> find_type(std::string_view name) noexcept {
  for (const auto& t : kTypes) {
    if (t.name == name) return t;
  }
  return std::nullopt;
}
constexpr std::optional<TypeInfo> find_type(TypeId id) noexcept {
  for (const auto& t : kTypes) {
    if (t.id == id) return t;
  }
  return std::nullopt;
}

namespace detail {
template <class T>
constexpr bool check_message() {
  static_assert(std::is_trivially_copyable_v<T>, "messages are copied as bytes by the rings");
  static_assert(std::is_default_constructible_v<T>);
  return kTypes[kIndexOf<T>].id == T::kId && kTypes[kIndexOf<T>].name == T::kName;
}
template <class... Ts>
constexpr bool check_all(TypeList<Ts...>) {
  return (check_message<Ts>() && ...);
}
static_assert(check_all(AllMessages{}));
}  // namespace detail

}  // namespace ringlet::wb
