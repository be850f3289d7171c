#pragma once
// The text form of any message, driven by visit_fields: fields in schema order, comma separated.
// Parsing fills a copy and hands it back only when every field parsed, so a bad string changes
// nothing anywhere.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "ringlet/whiteboard/field_codec.hpp"
#include "ringlet/whiteboard/messages.hpp"
#include "ringlet/whiteboard/result.hpp"

namespace ringlet::wb::detail {

/// `Type.field[index]: reason: "token"` (index < 0: no index).
Error field_error(std::string_view type, std::string_view field, std::ptrdiff_t index,
                  TextError reason, std::string_view token);
Error missing_field(std::string_view type, std::string_view field, std::ptrdiff_t index);
Error extra_fields(std::string_view type, std::size_t expected);

template <Message T>
std::string describe_message(const T& msg) {
  std::string out;
  out.reserve(64);
  bool first = true;
  visit_fields(msg, [&](std::string_view, const auto& field) {
    if (!first) out.push_back(',');
    first = false;
    append_text(out, field);
  });
  return out;
}

template <class V>
bool parse_one(Tokens& tokens, V& v, std::string_view type, std::string_view name,
               std::ptrdiff_t index, std::optional<Error>& err) {
  std::string_view token;
  if (!tokens.next(token)) {
    err = missing_field(type, name, index);
    return false;
  }
  if (const TextError e = parse_token(token, v); e != TextError::kNone) {
    err = field_error(type, name, index, e, token);
    return false;
  }
  return true;
}

template <class V, std::size_t N>
bool parse_one(Tokens& tokens, std::array<V, N>& v, std::string_view type, std::string_view name,
               std::ptrdiff_t, std::optional<Error>& err) {
  for (std::size_t i = 0; i < N; ++i) {
    if (!parse_one(tokens, v[i], type, name, static_cast<std::ptrdiff_t>(i), err)) return false;
  }
  return true;
}

template <Message T>
Result<T> parse_message(std::string_view text) {
  T out{};
  Tokens tokens(text);
  std::optional<Error> err;
  std::size_t fields = 0;
  visit_fields(out, [&](std::string_view name, auto& field) {
    ++fields;
    if (!err) parse_one(tokens, field, T::kName, name, -1, err);
  });
  if (err) return std::move(*err);
  if (std::string_view extra; tokens.next(extra)) return extra_fields(T::kName, fields);
  return out;
}

}  // namespace ringlet::wb::detail
