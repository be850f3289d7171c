#include "mlp_learner.hpp"

#include <opencv2/core.hpp>
#include <opencv2/ml.hpp>

namespace ringlet::experiments {

struct MlpLearner::Net {
  cv::Ptr<cv::ml::ANN_MLP> mlp;
};

MlpLearner::MlpLearner(std::uint64_t seed) : seed_(seed), net_(std::make_unique<Net>()) {}
MlpLearner::~MlpLearner() = default;

void MlpLearner::fit(std::span<const planning::Experience> train) {
  constexpr int kHidden = (planning::kFeatureCount + 1) / 2;
  cv::Mat samples(static_cast<int>(train.size()), planning::kFeatureCount, CV_32F);
  cv::Mat responses(static_cast<int>(train.size()), 1, CV_32F);
  for (int i = 0; i < samples.rows; ++i) {
    const auto& e = train[static_cast<std::size_t>(i)];
    for (int j = 0; j < planning::kFeatureCount; ++j) samples.at<float>(i, j) = static_cast<float>(e.features[static_cast<std::size_t>(j)]);
    responses.at<float>(i, 0) = static_cast<float>(e.achieved_speed);
  }
  cv::theRNG().state = seed_;
  net_->mlp = cv::ml::ANN_MLP::create();
  const cv::Mat layers = (cv::Mat_<int>(3, 1) << planning::kFeatureCount, kHidden, 1);
  net_->mlp->setLayerSizes(layers);
  net_->mlp->setActivationFunction(cv::ml::ANN_MLP::SIGMOID_SYM, 1.0, 1.0);
  net_->mlp->setTrainMethod(cv::ml::ANN_MLP::RPROP);
  net_->mlp->setTermCriteria(cv::TermCriteria(cv::TermCriteria::MAX_ITER, 500, 0.0));
  net_->mlp->train(samples, cv::ml::ROW_SAMPLE, responses);
}

double MlpLearner::predict(const planning::Features& x) const noexcept {
  try {
    cv::Mat in(1, planning::kFeatureCount, CV_32F);
    for (int j = 0; j < planning::kFeatureCount; ++j) in.at<float>(0, j) = static_cast<float>(x[static_cast<std::size_t>(j)]);
    cv::Mat out;
    net_->mlp->predict(in, out);
    return static_cast<double>(out.at<float>(0, 0));
  } catch (const cv::Exception&) {
    return 0.0;  // an unfitted net: no speed known
  }
}

}  // namespace ringlet::experiments
