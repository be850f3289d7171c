#pragma once
// What both whiteboard fuzz targets check on every message a decoder accepted: it survives the
// binary and the text forms, whatever it holds. Comparisons go through the encoded forms rather
// than operator==, because a double may be a NaN (never == itself) and a decoded NaN's payload
// bits are not carried by the text form ("nan").
#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include "ringlet/whiteboard/binary.hpp"
#include "ringlet/whiteboard/messages.hpp"

namespace ringlet::fuzz {

/// Traps unless encode -> decode -> encode gives the same bytes, and description() ->
/// from_string() -> description() the same text.
template <wb::Message T>
void check_round_trip(const T& msg) {
  std::array<std::byte, wb::encoded_size<T>()> first{};
  std::array<std::byte, wb::encoded_size<T>()> second{};
  if (wb::encode(msg, first) != first.size()) __builtin_trap();
  const wb::Result<T> decoded = wb::decode<T>(first);
  if (!decoded) __builtin_trap();
  if (wb::encode(*decoded, second) != second.size()) __builtin_trap();
  if (!std::equal(first.begin(), first.end(), second.begin())) __builtin_trap();

  const std::string text = msg.description();
  const wb::Result<T> parsed = T::from_string(text);
  if (!parsed) __builtin_trap();
  if (parsed->description() != text) __builtin_trap();
}

/// Traps unless a decoder's error names the type it was decoding ("BallBelief.x: ...").
template <wb::Message T>
void check_error(const std::string& error) {
  if (error.size() <= T::kName.size() || std::string_view(error).substr(0, T::kName.size()) != T::kName) {
    __builtin_trap();
  }
}

}  // namespace ringlet::fuzz
