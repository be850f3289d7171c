#include "ringlet/hal/image_header.hpp"

#include <algorithm>
#include <array>
#include <string_view>

namespace ringlet::hal {
namespace {

constexpr std::array<std::uint8_t, 8> kPngSignature{0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};

std::uint32_t be32(std::span<const std::uint8_t> b, std::size_t at) noexcept {
  return (static_cast<std::uint32_t>(b[at]) << 24) | (static_cast<std::uint32_t>(b[at + 1]) << 16) |
         (static_cast<std::uint32_t>(b[at + 2]) << 8) | static_cast<std::uint32_t>(b[at + 3]);
}
std::uint32_t be16(std::span<const std::uint8_t> b, std::size_t at) noexcept {
  return (static_cast<std::uint32_t>(b[at]) << 8) | static_cast<std::uint32_t>(b[at + 1]);
}

ImageProbe refuse(std::string why) { return {std::nullopt, std::move(why)}; }

ImageProbe sized(ImageFormat format, std::uint64_t width, std::uint64_t height, std::size_t max_pixels) {
  const std::string dims = std::to_string(width) + "x" + std::to_string(height);
  if (width == 0 || height == 0) return refuse(std::string(to_string(format)) + " header declares an empty image (" + dims + ")");
  // width, height < 2^32, so the product fits in 64 bits.
  if (width * height > max_pixels) {
    return refuse(std::string(to_string(format)) + " image is " + dims + " = " + std::to_string(width * height) +
                  " pixels, more than the limit of " + std::to_string(max_pixels));
  }
  return {ImageHeader{format, static_cast<int>(width), static_cast<int>(height)}, {}};
}

ImageProbe probe_png(std::span<const std::uint8_t> b, std::size_t max_pixels) {
  // Signature (8), then the first chunk, which must be IHDR: length 13 (4), "IHDR" (4), width (4),
  // height (4), ...
  if (b.size() < 24) return refuse("truncated PNG header (" + std::to_string(b.size()) + " bytes)");
  if (be32(b, 8) != 13 || b[12] != 'I' || b[13] != 'H' || b[14] != 'D' || b[15] != 'R') {
    return refuse("bad PNG header: the first chunk is not a 13-byte IHDR");
  }
  const std::uint32_t width = be32(b, 16);
  const std::uint32_t height = be32(b, 20);
  if (width > 0x7FFFFFFFU || height > 0x7FFFFFFFU) return refuse("bad PNG header: size above 2^31 - 1");
  return sized(ImageFormat::kPng, width, height, max_pixels);
}

bool is_sof(std::uint8_t marker) noexcept {
  // SOF0..SOF15 except DHT (C4), JPG (C8) and DAC (CC).
  return marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
}

ImageProbe probe_jpeg(std::span<const std::uint8_t> b, std::size_t max_pixels) {
  // After SOI, walk the markers as libjpeg's reader does (garbage before a marker and 0xFF fill
  // bytes are skipped; 0xFF 0x00 is not a marker) until the first frame header (SOFn), whose
  // height and width libjpeg will use.
  std::size_t at = 2;
  for (;;) {
    while (at < b.size() && b[at] != 0xFF) ++at;
    while (at < b.size() && b[at] == 0xFF) ++at;
    if (at >= b.size()) return refuse("JPEG ends before its frame header (SOF)");
    const std::uint8_t marker = b[at++];
    if (marker == 0x00) continue;
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) continue;  // TEM, RSTn: no length
    if (marker == 0xD8) return refuse("bad JPEG: a second start-of-image marker");
    if (marker == 0xD9) return refuse("JPEG ends (EOI) before its frame header (SOF)");
    if (marker == 0xDA) return refuse("bad JPEG: a scan (SOS) before the frame header (SOF)");
    if (at + 2 > b.size()) return refuse("truncated JPEG marker segment");
    const std::uint32_t length = be16(b, at);
    if (length < 2) return refuse("bad JPEG marker segment length " + std::to_string(length));
    if (is_sof(marker)) {
      // length (2), precision (1), height (2), width (2), components (1)
      if (length < 8 || at + 8 > b.size()) return refuse("truncated JPEG frame header (SOF)");
      return sized(ImageFormat::kJpeg, be16(b, at + 5), be16(b, at + 3), max_pixels);
    }
    at += length;
  }
}

}  // namespace

const char* to_string(ImageFormat format) noexcept { return format == ImageFormat::kPng ? "PNG" : "JPEG"; }

ImageProbe probe_image(std::span<const std::uint8_t> bytes, std::size_t max_pixels) {
  if (bytes.size() >= kPngSignature.size() &&
      std::equal(kPngSignature.begin(), kPngSignature.end(), bytes.begin())) {
    return probe_png(bytes, max_pixels);
  }
  // OpenCV (and libjpeg's callers) recognise a JPEG by FF D8 FF.
  if (bytes.size() >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF) return probe_jpeg(bytes, max_pixels);
  if (bytes.empty()) return refuse("empty file, not an image");
  return refuse("not a PNG or JPEG image");
}

}  // namespace ringlet::hal
