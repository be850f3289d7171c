// The HOG + linear SVM model file: whole or nothing (like the colour table's), and its inference.
#include "ringlet/vision/hog_svm.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>

#include "ringlet/hal/read_file.hpp"
#include "ringlet/vision/colour_table.hpp"  // crc32
#include "ringlet/vision/resample.hpp"

namespace ringlet::vision {
namespace {

constexpr std::array<std::uint8_t, 4> kMagic{'R', 'H', 'O', 'G'};
constexpr std::size_t kMaxFeatures = 1U << 20;  // far above any window this code accepts (256×256)

void put(std::vector<std::uint8_t>& b, std::uint64_t v, int bytes) {
  for (int k = 0; k < bytes; ++k) b.push_back(static_cast<std::uint8_t>((v >> (8 * k)) & 0xFFU));
}
std::uint64_t get(std::span<const std::uint8_t> b, std::size_t at, int bytes) noexcept {
  std::uint64_t v = 0;
  for (int k = 0; k < bytes; ++k) v |= static_cast<std::uint64_t>(b[at + static_cast<std::size_t>(k)]) << (8 * k);
  return v;
}

}  // namespace

const char* to_string(HogTarget t) noexcept {
  switch (t) {
    case HogTarget::kBall: return "ball";
    case HogTarget::kRobot: return "robot";
  }
  return "?";
}

HogSvm::HogSvm(HogTarget target, const HogParams& params, std::vector<float> weights, double bias, double threshold)
    : target_(target), params_(params), weights_(std::move(weights)), bias_(bias), threshold_(threshold) {}

std::string HogSvm::validate() const {
  if (target_ != HogTarget::kBall && target_ != HogTarget::kRobot) {
    return "target " + std::to_string(static_cast<int>(target_)) + " is neither 1 (ball) nor 2 (robot)";
  }
  if (std::string e = params_.check(); !e.empty()) return e;
  if (weights_.size() != static_cast<std::size_t>(params_.feature_length())) {
    return "feature count " + std::to_string(weights_.size()) + " does not match the HOG parameters (" +
           std::to_string(params_.feature_length()) + ")";
  }
  for (std::size_t i = 0; i < weights_.size(); ++i) {
    if (!std::isfinite(weights_[i])) return "weight " + std::to_string(i) + " is not a finite number";
  }
  if (!std::isfinite(bias_)) return "bias is not a finite number";
  if (!std::isfinite(threshold_)) return "threshold is not a finite number";
  return {};
}

std::vector<std::uint8_t> HogSvm::serialise() const {
  std::vector<std::uint8_t> b;
  b.reserve(kHeaderSize + 4 * weights_.size() + 4);
  for (const std::uint8_t m : kMagic) b.push_back(m);
  put(b, kFileVersion, 2);
  put(b, static_cast<std::uint8_t>(target_), 1);
  put(b, static_cast<std::uint64_t>(params_.bins), 1);
  put(b, static_cast<std::uint64_t>(params_.window_width), 2);
  put(b, static_cast<std::uint64_t>(params_.window_height), 2);
  put(b, static_cast<std::uint64_t>(params_.cell), 1);
  put(b, static_cast<std::uint64_t>(params_.block), 1);
  put(b, static_cast<std::uint64_t>(params_.block_stride), 1);
  put(b, 0, 1);
  put(b, weights_.size(), 4);
  put(b, std::bit_cast<std::uint64_t>(bias_), 8);
  put(b, std::bit_cast<std::uint64_t>(threshold_), 8);
  for (const float w : weights_) put(b, std::bit_cast<std::uint32_t>(w), 4);
  put(b, crc32(b), 4);
  return b;
}

std::string HogSvm::save(const std::filesystem::path& file) const {
  if (std::string e = validate(); !e.empty()) return "hog model " + file.string() + ": not written: " + e;
  const std::vector<std::uint8_t> bytes = serialise();
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) return "hog model " + file.string() + ": cannot open for writing";
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) return "hog model " + file.string() + ": write failed";
  return {};
}

HogSvmLoad HogSvm::load(const std::filesystem::path& file) {
  const hal::FileRead read = hal::read_file(file, "hog model", hal::kMaxTextFileBytes);
  if (!read.ok()) {
    const std::string prefix = file.string() + ": cannot read hog model: ";
    const bool ours = read.error.rfind(prefix, 0) == 0;
    return {std::nullopt, "hog model " + file.string() + ": " + (ours ? read.error.substr(prefix.size()) : read.error)};
  }
  return parse({reinterpret_cast<const std::uint8_t*>(read.bytes.data()), read.bytes.size()}, file.string());
}

HogSvmLoad HogSvm::parse(std::span<const std::uint8_t> bytes, std::string_view source) {
  const auto fail = [&](const std::string& what) {
    return HogSvmLoad{std::nullopt, "hog model " + std::string(source) + ": " + what};
  };
  if (bytes.size() < kHeaderSize) {
    return fail("truncated header: " + std::to_string(bytes.size()) + " bytes, need " + std::to_string(kHeaderSize));
  }
  if (!std::equal(kMagic.begin(), kMagic.end(), bytes.begin())) {
    return fail("not a HOG SVM model (bad magic, expected \"RHOG\")");
  }
  const auto version = static_cast<std::uint16_t>(get(bytes, 4, 2));
  if (version != kFileVersion) {
    return fail("unsupported version " + std::to_string(version) + " (this build reads version " +
                std::to_string(kFileVersion) + ")");
  }
  const auto target = static_cast<std::uint8_t>(get(bytes, 6, 1));
  if (target != 1 && target != 2) return fail("target " + std::to_string(target) + " is neither 1 (ball) nor 2 (robot)");
  HogParams p;
  p.bins = static_cast<int>(get(bytes, 7, 1));
  p.window_width = static_cast<int>(get(bytes, 8, 2));
  p.window_height = static_cast<int>(get(bytes, 10, 2));
  p.cell = static_cast<int>(get(bytes, 12, 1));
  p.block = static_cast<int>(get(bytes, 13, 1));
  p.block_stride = static_cast<int>(get(bytes, 14, 1));
  if (bytes[15] != 0) return fail("reserved byte 15 is " + std::to_string(bytes[15]) + ", expected 0");
  if (std::string e = p.check(); !e.empty()) return fail("bad HOG parameters: " + e);
  const std::uint64_t features = get(bytes, 16, 4);
  if (features != static_cast<std::uint64_t>(p.feature_length()) || features > kMaxFeatures) {
    return fail("feature count " + std::to_string(features) + " does not match the HOG parameters (" +
                std::to_string(p.feature_length()) + ")");
  }
  const std::size_t expected = kHeaderSize + 4 * features + 4;
  if (bytes.size() != expected) {
    return fail("size " + std::to_string(bytes.size()) + " bytes, expected " + std::to_string(expected) +
                (bytes.size() < expected ? " (truncated)" : " (trailing bytes)"));
  }
  const auto stored_crc = static_cast<std::uint32_t>(get(bytes, expected - 4, 4));
  if (crc32(bytes.first(expected - 4)) != stored_crc) return fail("CRC mismatch (corrupt file)");
  std::vector<float> weights(features);
  for (std::size_t i = 0; i < features; ++i) {
    weights[i] = std::bit_cast<float>(static_cast<std::uint32_t>(get(bytes, kHeaderSize + 4 * i, 4)));
  }
  HogSvm model(static_cast<HogTarget>(target), p, std::move(weights), std::bit_cast<double>(get(bytes, 20, 8)),
               std::bit_cast<double>(get(bytes, 28, 8)));
  if (std::string e = model.validate(); !e.empty()) return fail(e);
  return {std::move(model), {}};
}

double HogSvm::score(std::span<const float> features) const noexcept {
  if (features.size() != weights_.size()) return 0.0;
  double s = 0.0;
  for (std::size_t i = 0; i < features.size(); ++i) s += static_cast<double>(weights_[i]) * static_cast<double>(features[i]);
  return s + bias_;
}

HogClassifier::HogClassifier(HogSvm model)
    : model_(std::move(model)),
      hog_(model_.params()),
      patch_(static_cast<std::size_t>(model_.params().window_width) * static_cast<std::size_t>(model_.params().window_height)),
      features_(hog_.feature_length()) {}

double HogClassifier::score_window(const hal::FrameView& frame, double left, double top, double scale) noexcept {
  resample_luma(frame, left, top, scale, model_.params().window_width, model_.params().window_height, patch_);
  return score_patch(patch_);
}

double HogClassifier::score_patch(std::span<const std::uint8_t> patch) noexcept {
  if (!hog_.compute(patch, features_)) return 0.0;
  return model_.score(features_);
}

}  // namespace ringlet::vision
