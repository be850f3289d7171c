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
};

struct ImageProbe {
  std::optional<ImageHeader> header;  // set when the bytes look like a decodable PNG or JPEG of an allowed size
  std::string error;                  // otherwise what is wrong (without a file name: the caller adds it)
  [[nodiscard]] bool ok() const noexcept { return header.has_value(); }
};

/// The format and size an image file's header declares. Refuses anything but PNG and JPEG, a
/// truncated or malformed header, a zero size, and more than `max_pixels` pixels.
[[nodiscard]] ImageProbe probe_image(std::span<const std::uint8_t> bytes, std::size_t max_pixels = kMaxImagePixels);

[[nodiscard]] const char* to_string(ImageFormat format) noexcept;

}  // namespace ringlet::hal
