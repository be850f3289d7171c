#pragma once
// What an image file claims to be, read from its header before anything is decoded: PNG or JPEG
// and its size. A decoder allocates width × height × channels as soon as it has read the header,
// so a 60-byte file claiming 40000 × 40000 pixels would make it ask for gigabytes (OpenCV's own
// limit is 2^30 pixels and it throws). Everything that decodes images from outside (the vision
// tools, the OpenCV camera's replays, the fuzz targets) asks here first and refuses, with a
// message, what is not a PNG or a JPEG or is larger than the limit.
//
// No OpenCV: only the container's header is parsed (PNG: the IHDR chunk, which must come first;
// JPEG: the first SOFn marker, found by walking the markers the way libjpeg does).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace ringlet::hal {

enum class ImageFormat : std::uint8_t { kPng, kJpeg };

/// Larger pictures are refused: 4096 × 4096 is about 13× the NAO camera's largest mode
/// (1280 × 960) and 48 MiB as BGR.
inline constexpr std::size_t kMaxImagePixels = std::size_t{4096} * 4096;

struct ImageHeader {
  ImageFormat format = ImageFormat::kPng;
  int width = 0;
  int height = 0;
  /// Channels the file stores: 1 grey, 2 grey + alpha, 3 colour (palette PNGs count as colour),
  /// 4 colour + alpha; 0 when the header does not say (a PNG header cut before its colour type).
  int channels = 0;
  /// A grey picture: a decoder hands it out as three equal channels, which no colour
  /// classification can find a green field or an orange ball in.
  [[nodiscard]] bool grayscale() const noexcept { return channels == 1 || channels == 2; }
};

struct ImageProbe {
  std::optional<ImageHeader> header;  // set when the bytes look like a decodable PNG or JPEG of an allowed size
  std::string error;                  // otherwise what is wrong (without a file name: the caller adds it)
  [[nodiscard]] bool ok() const noexcept { return header.has_value(); }
};

/// The format and size an image file's header declares. Refuses anything but PNG and JPEG, a
/// truncated or malformed header, a zero size, and more than `max_pixels` pixels.
[[nodiscard]] ImageProbe probe_image(std::span<const std::uint8_t> bytes, std::size_t max_pixels = kMaxImagePixels);

/// Why the file does not hold its whole image, or empty when it does: a JPEG must reach its
/// end-of-image marker (FF D9) after the last scan, a PNG its IEND chunk. libjpeg decodes a JPEG
/// cut short with only a warning ("Premature end of JPEG file") and grey rows where the data
/// stopped, so OpenCV returns a picture that looks fine to the caller. The markers and chunks are
/// walked the way the decoders do (JPEG: segments by their lengths, entropy-coded data up to the
/// next marker, 0xFF 0x00 and RSTn being data; PNG: chunks by their lengths), so an EOI inside an
/// embedded thumbnail or bytes after the end do not mislead it. Linear in the file's size.
[[nodiscard]] std::string image_truncation(std::span<const std::uint8_t> bytes, ImageFormat format);

[[nodiscard]] const char* to_string(ImageFormat format) noexcept;

}  // namespace ringlet::hal
