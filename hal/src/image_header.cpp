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

ImageProbe sized(ImageFormat format, std::uint64_t width, std::uint64_t height, std::size_t max_pixels,
                 int channels) {
  const std::string dims = std::to_string(width) + "x" + std::to_string(height);
  if (width == 0 || height == 0) return refuse(std::string(to_string(format)) + " header declares an empty image (" + dims + ")");
  // width, height < 2^32, so the product fits in 64 bits.
  if (width * height > max_pixels) {
    return refuse(std::string(to_string(format)) + " image is " + dims + " = " + std::to_string(width * height) +
                  " pixels, more than the limit of " + std::to_string(max_pixels));
  }
  return {ImageHeader{format, static_cast<int>(width), static_cast<int>(height), channels}, {}};
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
  // ... bit depth (1), colour type (1): 0 grey, 2 RGB, 3 palette, 4 grey + alpha, 6 RGBA.
  int channels = 0;
  if (b.size() > 25) {
    switch (b[25]) {
      case 0: channels = 1; break;
      case 2: case 3: channels = 3; break;
      case 4: channels = 2; break;
      case 6: channels = 4; break;
      default: break;
    }
  }
  return sized(ImageFormat::kPng, width, height, max_pixels, channels);
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
      // Components: 1 is a grey JPEG, 3 (YCbCr) or 4 (CMYK) colour.
      const int components = b[at + 7];
      return sized(ImageFormat::kJpeg, be16(b, at + 5), be16(b, at + 3), max_pixels, components >= 3 ? 3 : components);
    }
    at += length;
  }
}

bool is_rst(std::uint8_t marker) noexcept { return marker >= 0xD0 && marker <= 0xD7; }

std::string png_truncation(std::span<const std::uint8_t> b) {
  // Chunks after the signature: length (4), type (4), data (length), CRC (4); IEND ends the file.
  std::size_t at = kPngSignature.size();
  while (at + 8 <= b.size()) {
    const std::uint64_t length = be32(b, at);
    if (length > 0x7FFFFFFFU) return "bad PNG chunk length " + std::to_string(length) + " at byte " + std::to_string(at);
    const bool iend = b[at + 4] == 'I' && b[at + 5] == 'E' && b[at + 6] == 'N' && b[at + 7] == 'D';
    const std::uint64_t next = at + 12 + length;
    if (next > b.size()) break;
    if (iend) return {};
    at = static_cast<std::size_t>(next);
  }
  return "truncated PNG (no IEND chunk)";
}

std::string jpeg_truncation(std::span<const std::uint8_t> b) {
  std::size_t at = 2;  // after SOI
  for (;;) {
    while (at < b.size() && b[at] != 0xFF) ++at;
    while (at < b.size() && b[at] == 0xFF) ++at;
    if (at >= b.size()) break;
    const std::uint8_t marker = b[at++];
    if (marker == 0xD9) return {};                                    // EOI: the whole image is here
    if (marker == 0x00 || marker == 0x01 || is_rst(marker)) continue;  // no length
    if (marker == 0xD8) continue;  // a stray SOI: libjpeg's business, not a truncation
    if (at + 2 > b.size()) break;
    const std::size_t length = be16(b, at);
    if (length < 2) return "bad JPEG marker segment length " + std::to_string(length) + " at byte " + std::to_string(at);
    at += length;
    if (at > b.size()) break;
    if (marker == 0xDA) {
      // Entropy-coded data after the scan header runs to the next marker: 0xFF followed by
      // anything but 0x00 (a stuffed data byte), RSTn (inside the scan) or another 0xFF (fill).
      while (at + 1 < b.size() &&
             !(b[at] == 0xFF && b[at + 1] != 0x00 && b[at + 1] != 0xFF && !is_rst(b[at + 1]))) {
        ++at;
      }
      if (at + 1 >= b.size()) break;
    }
  }
  return "truncated JPEG (no end-of-image marker)";
}

}  // namespace

std::string image_truncation(std::span<const std::uint8_t> bytes, ImageFormat format) {
  return format == ImageFormat::kPng ? png_truncation(bytes) : jpeg_truncation(bytes);
}

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
