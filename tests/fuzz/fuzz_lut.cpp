// Fuzz target: the colour table (LUT) file format, ColourTable::parse(bytes, source). Any input
// must either give a whole, valid table or an error "colour table fuzz.lut: <what>"; any other
// exception, crash or sanitizer report is a bug. A table that parses is used the way the robot
// uses it (every pixel format classified, every class in range) and must survive
// serialise -> parse (the bytes `save` writes) unchanged, byte for byte: the format has exactly
// one encoding of a table, so the input itself is what serialise gives.
//
// Random bytes almost never carry a matching CRC-32, so an input that fails on the CRC alone is
// parsed a second time with its CRC corrected: that is how the fuzzer reaches the entry checks and
// the classification with entries it chose.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ringlet/hal/camera.hpp"
#include "ringlet/vision/class_image.hpp"
#include "ringlet/vision/colour_table.hpp"

namespace {

using ringlet::vision::ColourTable;
using ringlet::vision::ColourTableLoad;

constexpr std::string_view kPrefix = "colour table fuzz.lut: ";

void check_error(const std::string& error) {
  if (error.size() <= kPrefix.size() || std::string_view(error).substr(0, kPrefix.size()) != kPrefix) __builtin_trap();
}

/// A small frame of each pixel format whose bytes come from the input, classified below a
/// horizon row; every sampled class must be one of the four.
void classify_all_formats(const ColourTable& table, std::span<const std::uint8_t> bytes) {
  constexpr int kWidth = 16, kHeight = 8;
  std::array<std::uint8_t, kWidth * kHeight * 3> pixels{};
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = bytes.empty() ? 0 : bytes[(i * 7919U) % bytes.size()];
  ringlet::vision::ClassImage classes(kWidth, kHeight);
  const std::array<std::pair<ringlet::hal::PixelFormat, int>, 3> formats{
      {{ringlet::hal::PixelFormat::kYuyv, 2}, {ringlet::hal::PixelFormat::kBgr8, 3}, {ringlet::hal::PixelFormat::kGray8, 1}}};
  for (const auto& [format, bytes_per_pixel] : formats) {
    for (const int step : {1, 2}) {
      ringlet::hal::FrameView view;
      view.format = format;
      view.width = kWidth;
      view.height = kHeight;
      view.stride = kWidth * bytes_per_pixel;
      view.data = pixels.data();
      const int first_row = static_cast<int>(pixels[0] % kHeight);
      if (!classes.classify(view, table, first_row, step)) __builtin_trap();
      for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
          if (classes.sampled(x, y) && static_cast<int>(classes.at(x, y)) >= ringlet::vision::kColourClassCount) {
            __builtin_trap();
          }
        }
      }
    }
  }
  // Direct lookups at the corners of YUV space.
  for (const int y : {0, 255}) {
    for (const int u : {0, 255}) {
      for (const int v : {0, 128, 255}) {
        const auto c = table.lookup(static_cast<std::uint8_t>(y), static_cast<std::uint8_t>(u), static_cast<std::uint8_t>(v));
        if (static_cast<int>(c) >= ringlet::vision::kColourClassCount) __builtin_trap();
      }
    }
  }
}

void check_table(const ColourTable& table, std::span<const std::uint8_t> input) {
  const int bits = table.bin_bits();
  if (bits < ColourTable::kMinBinBits || bits > ColourTable::kMaxBinBits) __builtin_trap();
  if (table.size() != (std::size_t{1} << (3 * bits))) __builtin_trap();
  classify_all_formats(table, input);
  const std::vector<std::uint8_t> saved = table.serialise();
  if (saved.size() != input.size() || !std::equal(saved.begin(), saved.end(), input.begin())) __builtin_trap();
  const ColourTableLoad again = ColourTable::parse(saved, "fuzz.lut");
  if (!again.table || !again.error.empty() || !(*again.table == table)) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> input(data, size);
  const ColourTableLoad r = ColourTable::parse(input, "fuzz.lut");
  if (r.table) {
    if (!r.error.empty()) __builtin_trap();
    check_table(*r.table, input);
    return 0;
  }
  check_error(r.error);
  if (r.error.find("CRC mismatch") == std::string::npos) return 0;
  // Everything but the CRC was right: correct it (bytes 12..15, little-endian) and go on.
  std::vector<std::uint8_t> fixed(input.begin(), input.end());
  const std::uint32_t crc = ringlet::vision::crc32(std::span<const std::uint8_t>(fixed).subspan(16));
  for (std::size_t k = 0; k < 4; ++k) fixed[12 + k] = static_cast<std::uint8_t>(crc >> (8 * k));
  const ColourTableLoad second = ColourTable::parse(fixed, "fuzz.lut");
  if (second.table) {
    check_table(*second.table, fixed);
  } else {
    check_error(second.error);
    if (second.error.find("CRC mismatch") != std::string::npos) __builtin_trap();
  }
  return 0;
}
