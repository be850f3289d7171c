// Fuzz target: the whiteboard's text decoder (T::from_string, what post_text and the tools use).
// Input: a type name, a newline, then the message text ("BallBelief\ntrue,1.5,-0.25,0.1,false").
// An accepted message must survive both encodings (wb_round_trip.hpp); a refused one must get an
// error naming the type. Decoders report errors as values: any exception is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>

#include "ringlet/whiteboard/messages.hpp"
#include "wb_round_trip.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::size_t newline = input.find('\n');
  if (newline == std::string_view::npos) return 0;
  const std::string_view name = input.substr(0, newline);
  const std::string_view text = input.substr(newline + 1);
  ringlet::wb::for_each_type([&](auto type) {
    using T = typename decltype(type)::type;
    if (T::kName != name) return;
    const ringlet::wb::Result<T> msg = T::from_string(text);
    if (msg) {
      ringlet::fuzz::check_round_trip(*msg);
    } else {
      ringlet::fuzz::check_error<T>(msg.error());
    }
  });
  return 0;
}
