#pragma once
// The training itself: windows → our HOG → OpenCV's linear SVM (cv::ml::SVM, C_SVC, LINEAR) →
// our model file's weights, bias and threshold. Deterministic for a seed: the samples are drawn
// with SplitMix64, and OpenCV's SMO solver has no randomness.
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/ml.hpp>

#include "ringlet/vision/hog_svm.hpp"
#include "samples.hpp"

namespace ringlet::vision::train {

struct TrainConfig {
  HogTarget target = HogTarget::kBall;
  std::uint64_t seed = 1;
  int jitter = 4;                // windows per true object: the true one and jittered ones (scale ±10 %, shift ±8 %)
  int negatives_per_frame = 20;  // random windows not overlapping the truth
  int hard_rounds = 1;           // rounds of hard-negative mining (retraining each time)
  int hard_tries_per_frame = 80; // random windows scored per frame and round
  int hard_per_frame = 10;       // false positives kept per frame and round
  double validation_share = 0.2; // frames (and patches) held out, chosen by a seeded hash
  double c = 0.01;               // SVM soft-margin C
  double min_precision = 0.95;   // threshold: the highest validation recall at this precision
};

struct Metrics {
  int tp = 0, fp = 0, fn = 0, tn = 0;
  [[nodiscard]] double precision() const { return tp + fp > 0 ? static_cast<double>(tp) / (tp + fp) : 1.0; }
  [[nodiscard]] double recall() const { return tp + fn > 0 ? static_cast<double>(tp) / (tp + fn) : 0.0; }
};

/// Samples as rows of features, with labels (+1 target, −1 not) and whether each is held out.
struct SampleMatrix {
  std::vector<float> features;  // rows × length
  std::vector<int> labels;
  std::vector<bool> validation;
  int length = 0;
  [[nodiscard]] int rows() const { return static_cast<int>(labels.size()); }
  [[nodiscard]] std::span<const float> row(int i) const {
    return {features.data() + static_cast<std::size_t>(i) * static_cast<std::size_t>(length), static_cast<std::size_t>(length)};
  }
};

struct TrainResult {
  HogSvm model;
  Metrics training, validation;
  int positives = 0, negatives = 0, hard_negatives = 0;
  int validation_positives = 0, validation_negatives = 0;
  bool precision_reached = true;  // a threshold met min_precision on the validation set
  cv::Ptr<cv::ml::SVM> svm;       // OpenCV's model (for the round-trip test)
  double opencv_sign = 1.0;       // our score = sign × OpenCV's raw decision value
  std::vector<std::string> log;
  int proposal_positives = 0, proposal_negatives = 0;  // of the samples: the detector's proposals
};

/// Trains from labelled frames and/or patches (either may be empty, not both). ToolError when
/// there is no positive or no negative sample to train on.
[[nodiscard]] TrainResult train_hog(const std::vector<LabelledFrame>& frames, const PatchSet& patches,
                                    const TrainConfig& config);

/// Which frame (or patch) indices are held out: a seeded hash, so the split does not depend on
/// the order in which sources were given beyond the index.
[[nodiscard]] bool held_out(std::uint64_t seed, std::uint64_t index, double share);

}  // namespace ringlet::vision::train
