// Writes the whiteboard fuzz targets' seed corpora: for every schema type, a default message and
// one with every field set (strings with characters that need escaping, a negative zero, a
// non-default enum), in the text form (corpus/wb_text/<Name>_*.txt: "Name\n<fields>") and the
// binary form (corpus/wb_binary/<Name>_*.bin). Run by hand after a schema change:
//   build/fuzz/tests/fuzz/ringlet_fuzz_wb_seeds tests/fuzz/corpus
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <type_traits>

#include "ringlet/whiteboard/binary.hpp"
#include "ringlet/whiteboard/messages.hpp"

namespace {

namespace wb = ringlet::wb;

template <class V>
void fill(V& v, int i) {
  if constexpr (std::is_same_v<V, bool>) {
    v = true;
  } else if constexpr (std::is_same_v<V, double>) {
    v = i % 3 == 0 ? -0.0 : 1.5 * i - 0.25;
  } else if constexpr (wb::SchemaEnum<V>) {
    v = std::end(wb::EnumTraits<V>::kEntries)[-1].value;
  } else if constexpr (std::is_integral_v<V>) {
    v = static_cast<V>(i + 3);
  } else if constexpr (requires { V::kCapacity; }) {
    v = "Loop, \\ \t\x01 end";
  } else {
    for (std::size_t k = 0; k < v.size(); ++k) fill(v[k], i + static_cast<int>(k));
  }
}

template <wb::Message T>
void write(const std::filesystem::path& dir, const T& msg, const char* variant) {
  const std::string stem = std::string(T::kName) + "_" + variant;
  std::ofstream(dir / "wb_text" / (stem + ".txt"), std::ios::binary) << T::kName << '\n' << msg.description();
  std::array<std::byte, wb::encoded_size<T>()> bytes{};
  (void)wb::encode(msg, bytes);
  std::ofstream(dir / "wb_binary" / (stem + ".bin"), std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s CORPUS_DIR\n", argv[0]);
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir / "wb_text");
  std::filesystem::create_directories(dir / "wb_binary");
  wb::for_each_type([&](auto type) {
    using T = typename decltype(type)::type;
    write(dir, T{}, "default");
    T filled{};
    int i = 0;
    wb::visit_fields(filled, [&i](std::string_view, auto& field) { fill(field, ++i); });
    write(dir, filled, "filled");
  });
  return 0;
}
