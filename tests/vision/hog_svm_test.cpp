// The HOG SVM model file: a round trip, and every way a file can be wrong gives an error naming
// the file and the problem, never a model (truncations at every length, every single-byte
// corruption of the header, bad magic, wrong feature count, trailing bytes, NaN weights).
#include <gtest/gtest.h>

#include <bit>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <tuple>

#include "ringlet/vision/hog_svm.hpp"
#include "ringlet/vision/prng.hpp"
#include "ringlet/vision/resample.hpp"
#include "temp_dir.hpp"

namespace ringlet::vision {
namespace {

HogSvm make_model(HogTarget target = HogTarget::kBall, HogParams p = HogParams::ball()) {
  std::vector<float> w(static_cast<std::size_t>(p.feature_length()));
  SplitMix64 g(7);
  for (float& x : w) x = static_cast<float>(static_cast<double>(g.below(2001)) / 1000.0 - 1.0);
  return HogSvm(target, p, std::move(w), -0.25, 0.5);
}

std::string parse_error(const std::vector<std::uint8_t>& bytes) {
  const HogSvmLoad l = HogSvm::parse(bytes, "m.hog");
  EXPECT_FALSE(l.model.has_value());
  return l.error;
}

TEST(HogSvm, RoundTripThroughAFile) {
  const HogSvm m = make_model(HogTarget::kRobot, HogParams::robot());
  ASSERT_EQ(m.validate(), "");
  const ringlet::test::TempDir tmp("ringlet_hog_svm");
  const auto path = tmp / "roundtrip.hog";
  ASSERT_EQ(m.save(path), "");
  const HogSvmLoad l = HogSvm::load(path);
  ASSERT_TRUE(l.model.has_value()) << l.error;
  EXPECT_EQ(*l.model, m);
  EXPECT_EQ(l.model->target(), HogTarget::kRobot);
  EXPECT_EQ(l.model->params(), HogParams::robot());
  EXPECT_EQ(std::filesystem::file_size(path), HogSvm::kHeaderSize + 4 * 756 + 4);
}

TEST(HogSvm, ScoreIsDotProductPlusBias) {
  const HogSvm m = make_model();
  std::vector<float> x(m.weights().size(), 0.0f);
  EXPECT_DOUBLE_EQ(m.score(x), -0.25);
  x[3] = 2.0f;
  EXPECT_DOUBLE_EQ(m.score(x), 2.0 * static_cast<double>(m.weights()[3]) - 0.25);
  EXPECT_EQ(m.score(std::vector<float>(5, 1.0f)), 0.0);  // wrong length: nothing
}

TEST(HogSvm, EveryTruncationIsRefused) {
  const std::vector<std::uint8_t> good = make_model().serialise();
  for (std::size_t n = 0; n < good.size(); ++n) {
    const std::string e = parse_error({good.begin(), good.begin() + static_cast<std::ptrdiff_t>(n)});
    ASSERT_EQ(e.rfind("hog model m.hog: ", 0), 0U) << e;
    if (n < HogSvm::kHeaderSize) {
      EXPECT_NE(e.find("truncated header"), std::string::npos) << n << ": " << e;
    } else {
      EXPECT_NE(e.find("(truncated)"), std::string::npos) << n << ": " << e;
    }
  }
}

TEST(HogSvm, EveryCorruptByteIsRefused) {
  const std::vector<std::uint8_t> good = make_model().serialise();
  for (std::size_t i = 0; i < good.size(); i += (i < 64 ? 1 : 97)) {
    for (const std::uint8_t flip : {std::uint8_t{0x01}, std::uint8_t{0x80}, std::uint8_t{0xFF}}) {
      std::vector<std::uint8_t> bad = good;
      bad[i] = static_cast<std::uint8_t>(bad[i] ^ flip);
      EXPECT_EQ(parse_error(bad).rfind("hog model m.hog: ", 0), 0U) << "byte " << i;
    }
  }
}

TEST(HogSvm, NamedErrors) {
  const std::vector<std::uint8_t> good = make_model().serialise();
  auto bad = good;
  bad[0] = 'X';
  EXPECT_NE(parse_error(bad).find("bad magic, expected \"RHOG\""), std::string::npos);
  bad = good;
  bad[4] = 9;
  EXPECT_NE(parse_error(bad).find("unsupported version 9"), std::string::npos);
  bad = good;
  bad[6] = 3;
  EXPECT_NE(parse_error(bad).find("target 3 is neither"), std::string::npos);
  bad = good;
  bad[8] = 30;  // window width 30: not a whole number of cells
  EXPECT_NE(parse_error(bad).find("bad HOG parameters"), std::string::npos);
  bad = good;
  bad[16] = 100;  // feature count 100 ≠ 324
  bad[17] = 0;
  EXPECT_NE(parse_error(bad).find("feature count 100 does not match"), std::string::npos);
  bad = good;
  bad.push_back(0);
  EXPECT_NE(parse_error(bad).find("(trailing bytes)"), std::string::npos);
  bad = good;
  bad[HogSvm::kHeaderSize + 5] ^= 0x10;
  EXPECT_NE(parse_error(bad).find("CRC mismatch"), std::string::npos);

  // A NaN weight with a correct CRC: refused by name.
  HogSvm nan_model = make_model();
  std::vector<float> w(nan_model.weights().begin(), nan_model.weights().end());
  w[17] = std::bit_cast<float>(0x7FC00000U);
  const HogSvm with_nan(HogTarget::kBall, HogParams::ball(), w, 0.0, 0.0);
  EXPECT_NE(parse_error(with_nan.serialise()).find("weight 17 is not a finite number"), std::string::npos);
  EXPECT_NE(with_nan.save("/tmp/never.hog").find("not written"), std::string::npos);
}

TEST(HogSvm, LoadNamesTheFile) {
  EXPECT_EQ(HogSvm::load("/nonexistent/ball.hog").error, "hog model /nonexistent/ball.hog: No such file or directory");
  EXPECT_EQ(HogSvm::load("/tmp").error, "hog model /tmp: not a regular file (a directory)");
  EXPECT_EQ(HogSvm::load("/dev/zero").error, "hog model /dev/zero: not a regular file (a character device)");
}

TEST(HogSvm, RandomBytesNeverGiveAModel) {
  SplitMix64 g(99);
  for (int k = 0; k < 2000; ++k) {
    std::vector<std::uint8_t> bytes(g.below(400));
    for (auto& b : bytes) b = static_cast<std::uint8_t>(g.below(256));
    if (bytes.size() >= 4 && k % 2 == 0) std::copy_n("RHOG", 4, bytes.begin());
    EXPECT_FALSE(HogSvm::parse(bytes, "fuzz").model.has_value());
  }
}

// The committed models load, are for what their names say, and their recipes say they were
// trained on ringlet-dataset frames (not the trainer's synthetic bootstrap frames) with a command.
TEST(HogSvm, CommittedModelsLoad) {
  const std::filesystem::path dir = RINGLET_VISION_MODELS_DIR;
  for (const auto& [name, target, params] : {std::tuple{"ball.hog", HogTarget::kBall, HogParams::ball()},
                                             std::tuple{"robot.hog", HogTarget::kRobot, HogParams::robot()}}) {
    const HogSvmLoad l = HogSvm::load(dir / name);
    ASSERT_TRUE(l.model.has_value()) << l.error;
    EXPECT_EQ(l.model->target(), target);
    EXPECT_EQ(l.model->params(), params);
    std::ifstream recipe(dir / (std::string(name) + ".recipe.txt"));
    const std::string text((std::istreambuf_iterator<char>(recipe)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("bootstrap: no"), std::string::npos) << name;
    EXPECT_NE(text.find("\"generator\":\"ringlet-dataset\""), std::string::npos) << name;
    EXPECT_NE(text.find("command: ringlet-train-hog"), std::string::npos) << name;
  }
}

// The descriptor's exact bits: the gradient pass is vectorised (vision/CMakeLists.txt), and SSE on
// x86-64 and NEON on aarch64 must give what a scalar pass would, bit for bit, so that a simulated
// run is the same on both. The same constant is checked in both trees (the aarch64 one under
// qemu). Patches: noise (every octant and bin, both wraps), ramps, flat (zero gradients).
TEST(HogExtractor, DescriptorBitsAreTheSameOnEveryTarget) {
  std::uint64_t hash = 1469598103934665603ULL;  // FNV-1a over every float's bits
  for (const HogParams& p : {HogParams::ball(), HogParams::robot()}) {
    HogExtractor hog(p);
    std::vector<float> out(hog.feature_length());
    std::vector<std::uint8_t> patch(static_cast<std::size_t>(p.window_width * p.window_height));
    SplitMix64 g(11);
    for (int kind = 0; kind < 12; ++kind) {
      for (int y = 0; y < p.window_height; ++y) {
        for (int x = 0; x < p.window_width; ++x) {
          const int ramp = (kind * 7 + x * (kind % 5 - 2) + y * (kind % 3 - 1) * 3) & 255;
          const int value = kind < 6 ? static_cast<int>(g.below(256)) : kind < 11 ? ramp : 90;
          patch[static_cast<std::size_t>(y * p.window_width + x)] = static_cast<std::uint8_t>(value);
        }
      }
      ASSERT_TRUE(hog.compute(patch, out));
      for (const float f : out) {
        hash ^= std::bit_cast<std::uint32_t>(f);
        hash *= 1099511628211ULL;
      }
    }
  }
  EXPECT_EQ(hash, 0x2de9e4aad7852e37ULL) << std::hex << hash;
}

TEST(Resample, IdentityAndClampAndSmoothing) {
  // A horizontal ramp, 64×48 Gray8: at scale 1 the window is the frame's pixels.
  std::vector<std::uint8_t> img(64 * 48);
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 64; ++x) img[static_cast<std::size_t>(y * 64 + x)] = static_cast<std::uint8_t>(x * 4);
  }
  hal::FrameView f{};
  f.width = 64;
  f.height = 48;
  f.stride = 64;
  f.format = hal::PixelFormat::kGray8;
  f.data = img.data();
  std::vector<std::uint8_t> out(8 * 8);
  resample_luma(f, 10, 5, 1.0, 8, 8, out);
  for (int j = 0; j < 8; ++j) EXPECT_EQ(out[static_cast<std::size_t>(j)], (10 + j) * 4);
  // Half-pixel positions interpolate: (10.5 + j·1) → between columns.
  resample_luma(f, 10.5, 5, 1.0, 8, 8, out);
  EXPECT_EQ(out[0], 42);
  // Outside the frame: the border column.
  resample_luma(f, -20, 5, 1.0, 8, 8, out);
  EXPECT_EQ(out[0], 0);
  resample_luma(f, 100, 5, 1.0, 8, 8, out);
  EXPECT_EQ(out[7], 252);
  // Scale 4 on a linear ramp: the four-sample average equals the centre sample.
  resample_luma(f, 0, 0, 4.0, 8, 8, out);
  EXPECT_EQ(out[1], 6 * 4 - 2);  // centre x = 6 → pixel-centre coordinate 5.5 → 22
}

}  // namespace
}  // namespace ringlet::vision
