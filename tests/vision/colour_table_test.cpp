// The colour LUT: threshold and example builders, confusion, the file format and every way a
// file can be wrong (each error names the file and the problem; nothing half-loaded).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "ringlet/vision/colour_table.hpp"

namespace ringlet::vision {
namespace {

Yuv from_bgr(std::uint8_t b, std::uint8_t g, std::uint8_t r) { return bgr_to_yuv(b, g, r); }

TEST(Bt601, KnownColours) {
  const Yuv white = bgr_to_yuv(255, 255, 255);
  EXPECT_EQ(white.y, 255);
  EXPECT_EQ(white.u, 128);
  EXPECT_EQ(white.v, 128);
  const Yuv black = bgr_to_yuv(0, 0, 0);
  EXPECT_EQ(black.y, 0);
  EXPECT_EQ(black.u, 128);
  const Yuv red = bgr_to_yuv(0, 0, 255);  // Y 76.2, U 84.9, V 255.5 → clamped
  EXPECT_EQ(red.y, 76);
  EXPECT_EQ(red.u, 85);
  EXPECT_EQ(red.v, 255);
}

TEST(ColourTable, DefaultThresholdsClassifyFieldColoursUnderVariedLight) {
  const ColourTable t = ColourTable::from_thresholds({});
  EXPECT_EQ(t.size(), 64U * 64U * 64U);
  for (const double light : {0.6, 0.8, 1.0, 1.2}) {
    const auto s = [light](int c) { return static_cast<std::uint8_t>(std::min(255.0, c * light)); };
    SCOPED_TRACE(light);
    EXPECT_EQ(t.lookup(from_bgr(s(40), s(140), s(40))), ColourClass::kField);
    EXPECT_EQ(t.lookup(from_bgr(s(0), s(120), s(255))), ColourClass::kBall);
  }
  for (const int w : {200, 235, 255}) {
    const auto c = static_cast<std::uint8_t>(w);
    EXPECT_EQ(t.lookup(from_bgr(c, c, c)), ColourClass::kLine) << w;
  }
  EXPECT_EQ(t.lookup(from_bgr(130, 120, 110)), ColourClass::kOther);  // grey wall
  EXPECT_EQ(t.lookup(from_bgr(20, 20, 20)), ColourClass::kOther);     // black
  EXPECT_EQ(t.lookup(from_bgr(200, 60, 30)), ColourClass::kOther);    // blue
}

TEST(ColourTable, BinIndexUsesTheTopBits) {
  ColourTable t;
  t.set_bin(t.index(0xFF, 0x00, 0x80), ColourClass::kBall);
  EXPECT_EQ(t.lookup(0xFC, 0x03, 0x83), ColourClass::kBall);  // same top 6 bits
  EXPECT_EQ(t.lookup(0xFB, 0x03, 0x83), ColourClass::kOther);
  const Yuv c = t.bin_centre(t.index(0xFF, 0x00, 0x80));
  EXPECT_EQ(c.y, 0xFE);
  EXPECT_EQ(c.u, 0x02);
  EXPECT_EQ(c.v, 0x82);
}

TEST(ColourTable, ExamplesMajorityAndFill) {
  std::vector<LabelledSample> s;
  for (int i = 0; i < 3; ++i) s.push_back({{100, 90, 90}, ColourClass::kField});
  s.push_back({{100, 90, 90}, ColourClass::kLine});  // outvoted
  s.push_back({{240, 128, 128}, ColourClass::kLine});
  s.push_back({{240, 129, 129}, ColourClass::kBall});  // same bin, one vote each: lower id wins
  const ColourTable other = ColourTable::from_examples(s, {EmptyBinFill::kOther, 3});
  EXPECT_EQ(other.lookup(100, 90, 90), ColourClass::kField);
  EXPECT_EQ(other.lookup(240, 128, 128), ColourClass::kLine);
  EXPECT_EQ(other.lookup(100, 98, 90), ColourClass::kOther);  // empty bin stays other
  const ColourTable near = ColourTable::from_examples(s, {EmptyBinFill::kNearest, 3});
  EXPECT_EQ(near.lookup(100, 98, 90), ColourClass::kField);    // 2 bins away
  EXPECT_EQ(near.lookup(100, 90, 110), ColourClass::kOther);   // 5 bins away: beyond the limit
  EXPECT_EQ(near.lookup(232, 128, 128), ColourClass::kLine);   // 2 bins below the line example
}

TEST(ColourTable, ConfusionCountsPrecisionRecall) {
  const ColourTable t = ColourTable::from_thresholds({});
  std::vector<LabelledSample> s{{from_bgr(40, 140, 40), ColourClass::kField},
                                {from_bgr(40, 140, 40), ColourClass::kField},
                                {from_bgr(235, 235, 235), ColourClass::kLine},
                                {from_bgr(40, 140, 40), ColourClass::kLine},  // mislabelled: predicted field
                                {from_bgr(0, 120, 255), ColourClass::kBall}};
  const Confusion c = t.confusion(s);
  EXPECT_EQ(c.total(), 5U);
  EXPECT_EQ(c.counts[1][1], 2U);
  EXPECT_EQ(c.counts[2][1], 1U);
  EXPECT_DOUBLE_EQ(c.precision(ColourClass::kField), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(c.recall(ColourClass::kField), 1.0);
  EXPECT_DOUBLE_EQ(c.recall(ColourClass::kLine), 0.5);
  EXPECT_DOUBLE_EQ(c.precision(ColourClass::kLine), 1.0);
  EXPECT_DOUBLE_EQ(c.precision(ColourClass::kOther), 1.0);  // nothing predicted other
}

TEST(Crc32, StandardCheckValue) {
  const std::string s = "123456789";
  EXPECT_EQ(crc32({reinterpret_cast<const std::uint8_t*>(s.data()), s.size()}), 0xCBF43926U);
}

class ColourTableFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("ringlet_lut_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path path(const char* name) const { return dir_ / name; }
  static std::vector<std::uint8_t> read(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  static void write(const std::filesystem::path& p, const std::vector<std::uint8_t>& b) {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
  }
  // Saves a good table, lets `mutate` damage the bytes, loads, and expects an error mentioning
  // the file and `what`.
  template <class F>
  void expect_error(const char* name, F mutate, const std::string& what) {
    const auto p = path(name);
    ASSERT_EQ(ColourTable::from_thresholds({}).save(p), "");
    auto bytes = read(p);
    mutate(bytes);
    write(p, bytes);
    const ColourTableLoad r = ColourTable::load(p);
    EXPECT_FALSE(r.table.has_value());
    EXPECT_NE(r.error.find(p.string()), std::string::npos) << r.error;
    EXPECT_NE(r.error.find(what), std::string::npos) << r.error;
  }
  std::filesystem::path dir_;
};

TEST_F(ColourTableFile, RoundTrip) {
  for (const int bits : {4, 6, 7}) {
    const ColourTable t = ColourTable::from_thresholds({}, bits);
    const auto p = path("t.lut");
    ASSERT_EQ(t.save(p), "");
    EXPECT_EQ(std::filesystem::file_size(p), 16U + (std::size_t{1} << (3 * bits)));
    const ColourTableLoad r = ColourTable::load(p);
    ASSERT_TRUE(r.table.has_value()) << r.error;
    EXPECT_EQ(r.error, "");
    EXPECT_EQ(*r.table, t);
    EXPECT_EQ(r.table->bin_bits(), bits);
  }
}

TEST_F(ColourTableFile, MissingFile) {
  const auto r = ColourTable::load(path("nope.lut"));
  EXPECT_FALSE(r.table);
  EXPECT_NE(r.error.find("nope.lut: No such file or directory"), std::string::npos) << r.error;
}

// Not files at all: hal::read_file refuses them before reading a byte and says what they are (both
// used to be reported as "no such file").
TEST_F(ColourTableFile, DirectoryAndDeviceAreNotRegularFiles) {
  const auto dir = ColourTable::load(dir_);
  EXPECT_FALSE(dir.table);
  EXPECT_NE(dir.error.find("colour table " + dir_.string() + ": not a regular file (a directory)"),
            std::string::npos) << dir.error;
  const auto zero = ColourTable::load("/dev/zero");
  EXPECT_FALSE(zero.table);
  EXPECT_NE(zero.error.find("colour table /dev/zero: not a regular file (a character device)"),
            std::string::npos) << zero.error;
}

TEST(ColourTableBytes, ParseIsTheFileFormatWithoutAFile) {
  const ColourTable t = ColourTable::from_thresholds({}, 5);
  const std::vector<std::uint8_t> bytes = t.serialise();
  ASSERT_EQ(bytes.size(), 16U + (std::size_t{1} << 15));
  const ColourTableLoad r = ColourTable::parse(bytes, "memory");
  ASSERT_TRUE(r.table) << r.error;
  EXPECT_EQ(*r.table, t);
  // The source names the bytes in errors.
  const std::vector<std::uint8_t> shortened(bytes.begin(), bytes.begin() + 20);
  const ColourTableLoad bad = ColourTable::parse(shortened, "fuzz input");
  EXPECT_FALSE(bad.table);
  EXPECT_EQ(bad.error, "colour table fuzz input: size 20 bytes, expected 32784 (truncated)");
  EXPECT_EQ(ColourTable::parse({}, "x").error, "colour table x: truncated header: 0 bytes, need 16");
}

TEST_F(ColourTableFile, EveryCorruptionIsNamed) {
  using B = std::vector<std::uint8_t>;
  expect_error("empty.lut", [](B& b) { b.clear(); }, "truncated header");
  expect_error("short.lut", [](B& b) { b.resize(10); }, "truncated header");
  expect_error("magic.lut", [](B& b) { b[0] = 'X'; }, "bad magic");
  expect_error("version.lut", [](B& b) { b[4] = 2; }, "unsupported version 2");
  expect_error("bits.lut", [](B& b) { b[6] = 9; }, "bin bits 9");
  expect_error("classes.lut", [](B& b) { b[7] = 5; }, "class count 5");
  expect_error("entries.lut", [](B& b) { b[8] = 1; }, "entry count");
  expect_error("truncated.lut", [](B& b) { b.resize(b.size() - 1); }, "(truncated)");
  expect_error("trailing.lut", [](B& b) { b.push_back(0); }, "(trailing bytes)");
  expect_error("crc.lut", [](B& b) { b[100] ^= 1; }, "CRC mismatch");
  // A bad class value with a matching CRC: only the range check catches it.
  expect_error(
      "range.lut",
      [](B& b) {
        b[16 + 7] = 9;
        const std::uint32_t c = crc32({b.data() + 16, b.size() - 16});
        for (std::size_t k = 0; k < 4; ++k) b[12 + k] = static_cast<std::uint8_t>(c >> (8 * k));
      },
      "entry 7 has class 9");
}

TEST_F(ColourTableFile, SaveToABadPathIsAnError) {
  const std::string e = ColourTable().save(path("no_dir") / "t.lut");
  EXPECT_NE(e.find("cannot open for writing"), std::string::npos) << e;
}

}  // namespace
}  // namespace ringlet::vision
