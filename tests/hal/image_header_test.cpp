// The image header probe: PNG and JPEG sizes read before decoding, and everything else refused
// with a reason (an oversized header must never reach a decoder); grey pictures recognised; a file
// cut short recognised by its missing end (JPEG's EOI marker, PNG's IEND chunk).
#include "ringlet/hal/image_header.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace {

using ringlet::hal::ImageFormat;
using ringlet::hal::image_truncation;
using ringlet::hal::probe_image;

std::vector<std::uint8_t> bytes(std::initializer_list<std::uint8_t> b) { return b; }

std::vector<std::uint8_t> png_header(std::uint32_t width, std::uint32_t height) {
  std::vector<std::uint8_t> b{0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A, 0, 0, 0, 13, 'I', 'H', 'D', 'R'};
  for (const std::uint32_t v : {width, height}) {
    for (int shift = 24; shift >= 0; shift -= 8) b.push_back(static_cast<std::uint8_t>(v >> shift));
  }
  for (const int x : {8, 2, 0, 0, 0, 0, 0, 0, 0}) b.push_back(static_cast<std::uint8_t>(x));  // depth, colour type, ..., CRC
  return b;
}

/// SOI, an APP0 segment, garbage bytes, fill bytes, then SOF0 with the given size.
std::vector<std::uint8_t> jpeg_header(std::uint16_t width, std::uint16_t height, std::uint8_t sof = 0xC0) {
  std::vector<std::uint8_t> b{0xFF, 0xD8, 0xFF, 0xE0, 0x00, 0x06, 'J', 'F', 'I', 'F', 0x12, 0x34, 0xFF, 0xFF, sof,
                              0x00, 0x11, 0x08};
  b.push_back(static_cast<std::uint8_t>(height >> 8));
  b.push_back(static_cast<std::uint8_t>(height & 0xFF));
  b.push_back(static_cast<std::uint8_t>(width >> 8));
  b.push_back(static_cast<std::uint8_t>(width & 0xFF));
  b.push_back(3);
  return b;
}

TEST(ImageHeader, ReadsThePngSize) {
  const auto p = probe_image(png_header(640, 480));
  ASSERT_TRUE(p.ok()) << p.error;
  EXPECT_EQ(p.header->format, ImageFormat::kPng);
  EXPECT_EQ(p.header->width, 640);
  EXPECT_EQ(p.header->height, 480);
}

TEST(ImageHeader, ReadsTheJpegSizeFromTheFirstFrameHeader) {
  const auto p = probe_image(jpeg_header(1280, 960, 0xC2));  // progressive
  ASSERT_TRUE(p.ok()) << p.error;
  EXPECT_EQ(p.header->format, ImageFormat::kJpeg);
  EXPECT_EQ(p.header->width, 1280);
  EXPECT_EQ(p.header->height, 960);
}

TEST(ImageHeader, RefusesAnOversizedPngBeforeDecoding) {
  const auto p = probe_image(png_header(40000, 40000));
  EXPECT_FALSE(p.ok());
  EXPECT_EQ(p.error, "PNG image is 40000x40000 = 1600000000 pixels, more than the limit of 16777216");
  EXPECT_FALSE(probe_image(png_header(0xFFFFFFFFU, 1)).ok());
  EXPECT_TRUE(probe_image(png_header(4096, 4096)).ok());
  EXPECT_FALSE(probe_image(png_header(4097, 4096)).ok());
  EXPECT_FALSE(probe_image(png_header(100, 100), 9999).ok());  // the caller's own limit
}

TEST(ImageHeader, RefusesAnOversizedOrEmptyJpeg) {
  EXPECT_NE(probe_image(jpeg_header(65535, 65535)).error.find("JPEG image is 65535x65535"), std::string::npos);
  EXPECT_NE(probe_image(jpeg_header(640, 0)).error.find("empty image"), std::string::npos);
}

TEST(ImageHeader, RefusesTruncatedAndMalformedHeaders) {
  auto png = png_header(64, 64);
  png.resize(20);
  EXPECT_NE(probe_image(png).error.find("truncated PNG header"), std::string::npos);
  png = png_header(64, 64);
  png[12] = 'X';
  EXPECT_NE(probe_image(png).error.find("not a 13-byte IHDR"), std::string::npos);

  auto jpeg = jpeg_header(64, 64);
  jpeg.resize(jpeg.size() - 3);
  EXPECT_NE(probe_image(jpeg).error.find("truncated JPEG frame header"), std::string::npos);
  EXPECT_NE(probe_image(bytes({0xFF, 0xD8, 0xFF, 0xD9})).error.find("EOI"), std::string::npos);
  EXPECT_NE(probe_image(bytes({0xFF, 0xD8, 0xFF, 0xDA, 0, 8})).error.find("SOS"), std::string::npos);
  EXPECT_NE(probe_image(bytes({0xFF, 0xD8, 0xFF, 0xE1, 0, 1})).error.find("length 1"), std::string::npos);
  EXPECT_NE(probe_image(bytes({0xFF, 0xD8, 0xFF, 0xE1, 0xFF, 0xFF, 1, 2})).error.find("ends before"), std::string::npos);
}

TEST(ImageHeader, RefusesWhatIsNotPngOrJpeg) {
  EXPECT_EQ(probe_image(bytes({})).error, "empty file, not an image");
  const std::string text = "this is text, not a PNG\n";
  EXPECT_EQ(probe_image({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()}).error,
            "not a PNG or JPEG image");
  EXPECT_EQ(probe_image(bytes({'B', 'M', 0, 0, 0, 0})).error, "not a PNG or JPEG image");  // BMP: not accepted
}

// ---- channels and completeness -----------------------------------------------------------------

/// A whole (tiny, structurally complete) JPEG: SOI, APP1 holding an embedded thumbnail's EOI,
/// SOF0 with `components`, DHT, SOS, entropy-coded data with a stuffed 0xFF 0x00 and a restart
/// marker, a second scan (progressive-like), fill bytes, EOI.
std::vector<std::uint8_t> whole_jpeg(std::uint8_t components) {
  std::vector<std::uint8_t> b{0xFF, 0xD8,                                      // SOI
                              0xFF, 0xE1, 0x00, 0x08, 'E', 'x', 0xFF, 0xD8, 0xFF, 0xD9,  // APP1, a thumbnail's SOI/EOI
                              0xFF, 0xC0, 0x00, static_cast<std::uint8_t>(8 + 3 * components), 0x08, 0x00, 0x10, 0x00,
                              0x10, components};
  for (std::uint8_t c = 0; c < components; ++c) {
    b.insert(b.end(), {static_cast<std::uint8_t>(c + 1), 0x11, 0x00});
  }
  b.insert(b.end(), {0xFF, 0xC4, 0x00, 0x04, 0x00, 0x00,                          // DHT (a stand-in)
                     0xFF, 0xDA, 0x00, 0x08, 0x01, 0x01, 0x00, 0x00, 0x3F, 0x00,  // SOS
                     0x12, 0xFF, 0x00, 0x34, 0xFF, 0xD0, 0x56, 0xFF, 0x00, 0x78,  // data, stuffing, RST0
                     0xFF, 0xDA, 0x00, 0x08, 0x01, 0x01, 0x00, 0x00, 0x3F, 0x00,  // a second scan
                     0x9A, 0xBC, 0xFF, 0xFF, 0xD9});                               // data, fill, EOI
  return b;
}

std::vector<std::uint8_t> whole_png(std::uint8_t colour_type) {
  auto b = png_header(16, 16);
  b[25] = colour_type;
  // png_header ends with IHDR's CRC; then an IDAT of 3 bytes and IEND.
  b.insert(b.end(), {0, 0, 0, 3, 'I', 'D', 'A', 'T', 1, 2, 3, 0, 0, 0, 0, 0, 0, 0, 0, 'I', 'E', 'N', 'D', 0, 0, 0, 0});
  return b;
}

TEST(ImageHeader, KnowsAGreyPicture) {
  const auto grey_jpeg = probe_image(whole_jpeg(1));
  ASSERT_TRUE(grey_jpeg.ok()) << grey_jpeg.error;
  EXPECT_EQ(grey_jpeg.header->channels, 1);
  EXPECT_TRUE(grey_jpeg.header->grayscale());
  const auto colour_jpeg = probe_image(whole_jpeg(3));
  ASSERT_TRUE(colour_jpeg.ok());
  EXPECT_EQ(colour_jpeg.header->channels, 3);
  EXPECT_FALSE(colour_jpeg.header->grayscale());
  const std::pair<std::uint8_t, int> png_types[] = {{0, 1}, {2, 3}, {3, 3}, {4, 2}, {6, 4}};
  for (const auto& [type, channels] : png_types) {
    const auto p = probe_image(whole_png(type));
    ASSERT_TRUE(p.ok());
    EXPECT_EQ(p.header->channels, channels) << int{type};
    EXPECT_EQ(p.header->grayscale(), channels <= 2) << int{type};
  }
}

TEST(ImageHeader, AWholeFileIsNotTruncatedEvenWithBytesAfterItsEnd) {
  EXPECT_EQ(image_truncation(whole_jpeg(3), ImageFormat::kJpeg), "");
  EXPECT_EQ(image_truncation(whole_png(2), ImageFormat::kPng), "");
  auto jpeg = whole_jpeg(3);
  jpeg.insert(jpeg.end(), {0, 0, 0x42});  // padding some cameras append
  EXPECT_EQ(image_truncation(jpeg, ImageFormat::kJpeg), "");
}

// Cut at every byte, the file is truncated: the thumbnail's EOI inside APP1, the stuffed 0xFF 0x00,
// the restart marker and the fill bytes never pass for the end.
TEST(ImageHeader, AFileCutAtAnyByteIsTruncated) {
  const auto jpeg = whole_jpeg(3);
  for (std::size_t n = 3; n < jpeg.size(); ++n) {
    const std::vector<std::uint8_t> cut(jpeg.begin(), jpeg.begin() + static_cast<std::ptrdiff_t>(n));
    EXPECT_EQ(image_truncation(cut, ImageFormat::kJpeg), "truncated JPEG (no end-of-image marker)") << n;
  }
  const auto png = whole_png(2);
  for (std::size_t n = 8; n < png.size(); ++n) {
    const std::vector<std::uint8_t> cut(png.begin(), png.begin() + static_cast<std::ptrdiff_t>(n));
    EXPECT_EQ(image_truncation(cut, ImageFormat::kPng), "truncated PNG (no IEND chunk)") << n;
  }
}

TEST(ImageHeader, AMalformedLengthIsNamed) {
  auto png = whole_png(2);
  png[33] = 0xFF;  // IDAT's length: 0xFF000003, above 2^31 - 1
  EXPECT_EQ(image_truncation(png, ImageFormat::kPng), "bad PNG chunk length 4278190083 at byte 33");
  auto jpeg = whole_jpeg(3);
  jpeg[5] = 1;  // APP1's length below 2
  EXPECT_EQ(image_truncation(jpeg, ImageFormat::kJpeg), "bad JPEG marker segment length 1 at byte 4");
}

}  // namespace
