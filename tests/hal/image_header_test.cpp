// The image header probe: PNG and JPEG sizes read before decoding, and everything else refused
// with a reason (an oversized header must never reach a decoder).
#include "ringlet/hal/image_header.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

using ringlet::hal::ImageFormat;
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

}  // namespace
