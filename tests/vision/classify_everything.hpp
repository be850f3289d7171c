#pragma once
// A pipeline whose classifiers accept every window (weights 0.01, threshold -1e9), so every
// candidate the level allows is resampled, described and scored: for the tests and benchmarks
// that count, time or budget the classifications rather than judge them.
#include <memory>
#include <vector>

#include "ringlet/vision/hog_svm.hpp"
#include "ringlet/vision/pipeline.hpp"

namespace ringlet::vision::testing {

[[nodiscard]] inline HogSvm accept_all(HogTarget target, const HogParams& hog) {
  return HogSvm(target, hog, std::vector<float>(static_cast<std::size_t>(hog.feature_length()), 0.01f), 0.0, -1e9);
}

/// The black-and-white ball's pipeline (default colour table) with both accept-all classifiers.
[[nodiscard]] inline std::unique_ptr<VisionPipeline> pipeline_classifying_everything() {
  VisionConfig config;
  config.ball.mode = BallMode::kBlackWhite;
  auto p = std::make_unique<VisionPipeline>(config, ColourTable::from_thresholds({}));
  (void)p->set_classifier(accept_all(HogTarget::kBall, HogParams::ball()));
  (void)p->set_classifier(accept_all(HogTarget::kRobot, HogParams::robot()));
  return p;
}

}  // namespace ringlet::vision::testing
