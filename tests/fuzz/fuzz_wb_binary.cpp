// Fuzz target: the whiteboard's binary decoder (decode<T>, what post_binary routes datagrams to).
// Every type's decoder gets the same bytes: at most the one whose id is in the header may accept
// them, and an accepted message must survive both encodings (wb_round_trip.hpp); a refused one
// must get an error naming the type. Decoders report errors as values: any exception is a bug.
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

#include "ringlet/whiteboard/binary.hpp"
#include "ringlet/whiteboard/messages.hpp"
#include "wb_round_trip.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  const ringlet::wb::Result<ringlet::wb::WireHeader> header = ringlet::wb::peek_header(bytes);
  if (header.has_value() != (size >= ringlet::wb::kWireHeaderSize)) __builtin_trap();
  ringlet::wb::for_each_type([&](auto type) {
    using T = typename decltype(type)::type;
    const ringlet::wb::Result<T> msg = ringlet::wb::decode<T>(bytes);
    if (msg) {
      if (!header || header->id != T::kId) __builtin_trap();
      ringlet::fuzz::check_round_trip(*msg);
    } else {
      ringlet::fuzz::check_error<T>(msg.error());
    }
  });
  return 0;
}
