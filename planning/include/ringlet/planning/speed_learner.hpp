#pragma once
// The learners of Powers & Balch §IV (Table I) behind one interface: each predicts the average
// speed the reactive layer will achieve over a transition from its features. fit() is for
// training off the cycle path (it may allocate); predict() is what a cost model calls in the
// planner's slice, and never allocates.
//
// This file holds the interface and the two rules that learn nothing from the features: the
// training mean (Weka's ZeroR, the reference of the relative errors) and the paper's baseline.
#include <span>

#include "ringlet/planning/cost_model.hpp"
#include "ringlet/planning/experience.hpp"

namespace ringlet::planning {

class SpeedLearner {
 public:
  SpeedLearner() = default;
  SpeedLearner(const SpeedLearner&) = delete;
  SpeedLearner& operator=(const SpeedLearner&) = delete;
  virtual ~SpeedLearner() = default;

  /// Learns from `train` alone (each experience's achieved_speed is the label), replacing whatever
  /// was learnt before.
  virtual void fit(std::span<const Experience> train) = 0;
  /// The expected average speed (m/s) over a transition with features `x`.
  [[nodiscard]] virtual double predict(const Features& x) const noexcept = 0;
};

/// The mean label of the training set, whatever the features (Weka's ZeroR): a relative absolute
/// error of 100 % by definition.
class MeanLearner final : public SpeedLearner {
 public:
  void fit(std::span<const Experience> train) override {
    double sum = 0.0;
    for (const Experience& e : train) sum += e.achieved_speed;
    mean_ = train.empty() ? 0.0 : sum / static_cast<double>(train.size());
  }
  [[nodiscard]] double predict(const Features&) const noexcept override { return mean_; }

 private:
  double mean_ = 0.0;
};

/// The paper's baseline (§III-B) over the features: speed 0 when `from` or `to` holds more than
/// max_occupied occupied cells, else top speed; it learns nothing. Same rule as BinaryCostModel,
/// which reads counts: the features hold fractions of `cells_per_region` cells.
class BaselineLearner final : public SpeedLearner {
 public:
  BaselineLearner(const BinaryCostModel::Params& p, int cells_per_region) noexcept
      : params_(p), cells_(static_cast<double>(cells_per_region)) {}
  void fit(std::span<const Experience>) override {}
  [[nodiscard]] double predict(const Features& x) const noexcept override {
    return blocked(x[kFrom]) || blocked(x[kTo]) ? 0.0 : params_.top_speed;
  }

 private:
  /// Back to a count: a fraction of n cells times n is within an ulp of an integer.
  [[nodiscard]] bool blocked(double fraction) const noexcept {
    return static_cast<int>(fraction * cells_ + 0.5) > params_.max_occupied;
  }

  BinaryCostModel::Params params_;
  double cells_;
};

}  // namespace ringlet::planning
