#pragma once
// A linear SVM on HOG descriptors: the model file (written by the offline trainer
// ringlet-train-hog, vision/tools/train) and its inference, a dot product on fixed buffers.
//
// File (version 1, little-endian; vision/README.md "SVM model file"):
//   0 magic "RHOG" | 4 u16 version | 6 u8 target (1 ball, 2 robot) | 7 u8 bins
//   8 u16 window width | 10 u16 window height | 12 u8 cell px | 13 u8 block cells
//   14 u8 block stride cells | 15 u8 reserved = 0 | 16 u32 feature count
//   20 f64 bias | 28 f64 threshold | 36 feature count × f32 weights | then u32 CRC-32 of all before
// score(x) = w·x + bias (positive: the target); a detection needs score ≥ threshold (chosen by the
// trainer on its validation set).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ringlet/hal/camera.hpp"
#include "ringlet/vision/hog.hpp"

namespace ringlet::vision {

enum class HogTarget : std::uint8_t { kBall = 1, kRobot = 2 };
[[nodiscard]] const char* to_string(HogTarget t) noexcept;

struct HogSvmLoad;

class HogSvm {
 public:
  static constexpr std::uint16_t kFileVersion = 1;
  static constexpr std::size_t kHeaderSize = 36;

  /// A model from its parts; `weights` must have params.feature_length() entries, every number
  /// finite and params.check() empty (else the result of validate() says why).
  HogSvm(HogTarget target, const HogParams& params, std::vector<float> weights, double bias, double threshold);

  [[nodiscard]] static HogSvmLoad load(const std::filesystem::path& file);
  /// The same checks on bytes in memory; `source` names them in errors.
  [[nodiscard]] static HogSvmLoad parse(std::span<const std::uint8_t> bytes, std::string_view source);
  [[nodiscard]] std::vector<std::uint8_t> serialise() const;
  /// "" or an error naming the file.
  [[nodiscard]] std::string save(const std::filesystem::path& file) const;
  /// "" or what makes this model unusable.
  [[nodiscard]] std::string validate() const;

  [[nodiscard]] HogTarget target() const noexcept { return target_; }
  [[nodiscard]] const HogParams& params() const noexcept { return params_; }
  [[nodiscard]] std::span<const float> weights() const noexcept { return weights_; }
  [[nodiscard]] double bias() const noexcept { return bias_; }
  [[nodiscard]] double threshold() const noexcept { return threshold_; }

  /// w·x + bias, accumulated in double in index order (the same on every target); 0 if the
  /// length does not match.
  [[nodiscard]] double score(std::span<const float> features) const noexcept;

  friend bool operator==(const HogSvm&, const HogSvm&) = default;

 private:
  HogTarget target_;
  HogParams params_;
  std::vector<float> weights_;
  double bias_;
  double threshold_;
};

/// Either a whole model or an error "hog model <source>: <what>", never a partial model.
struct HogSvmLoad {
  std::optional<HogSvm> model;
  std::string error;
};

/// A model plus the buffers to run it: resample a window, compute its HOG, score it. Allocates
/// at construction only.
class HogClassifier {
 public:
  explicit HogClassifier(HogSvm model);
  [[nodiscard]] const HogSvm& model() const noexcept { return model_; }
  /// Scores the window of `frame` with top-left corner (left, top) and `scale` frame pixels per
  /// window pixel (resample.hpp).
  [[nodiscard]] double score_window(const hal::FrameView& frame, double left, double top, double scale) noexcept;
  /// Scores a patch already of the window's size.
  [[nodiscard]] double score_patch(std::span<const std::uint8_t> patch) noexcept;
  [[nodiscard]] std::span<const std::uint8_t> last_patch() const noexcept { return patch_; }

 private:
  HogSvm model_;
  HogExtractor hog_;
  std::vector<std::uint8_t> patch_;
  std::vector<float> features_;
};

}  // namespace ringlet::vision
