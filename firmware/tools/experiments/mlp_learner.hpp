#pragma once
// Table I's multilayer perceptron, on OpenCV's ml module (offline only: host builds with OpenCV).
// Weka's MultilayerPerceptron's shape: one hidden layer of (attributes + 1) / 2 = 6 sigmoid units,
// 500 epochs; but trained with RPROP (batch) instead of Weka's per-sample back-propagation
// (learning rate 0.3, momentum 0.2), which OpenCV runs ~20 µs a sample: 10 folds of 4500
// experiences took over 15 minutes on the shared 2-core machine. Deterministic: OpenCV draws the
// initial weights from the calling thread's cv::theRNG(), which fit() seeds, and main() sets
// OpenCV to one thread.
#include <cstdint>
#include <memory>

#include "ringlet/planning/speed_learner.hpp"

namespace ringlet::experiments {

class MlpLearner final : public planning::SpeedLearner {
 public:
  explicit MlpLearner(std::uint64_t seed);
  ~MlpLearner() override;
  void fit(std::span<const planning::Experience> train) override;
  [[nodiscard]] double predict(const planning::Features& x) const noexcept override;

 private:
  struct Net;
  std::uint64_t seed_;
  std::unique_ptr<Net> net_;
};

}  // namespace ringlet::experiments
