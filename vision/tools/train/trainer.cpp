// ringlet-train-hog's training (trainer.hpp).
#include "trainer.hpp"

#include <algorithm>
#include <cmath>

#include "ringlet/vision/prng.hpp"
#include "vision_io.hpp"

namespace ringlet::vision::train {
namespace {

using tools::ToolError;

HogParams params_for(HogTarget t) { return t == HogTarget::kBall ? HogParams::ball() : HogParams::robot(); }

double uniform(SplitMix64& g, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(g.below(1000001)) / 1e6;
}

// A random window of a plausible size for the target, with the object box it implies.
WindowPlacement random_window(HogTarget target, const HogParams& hog, const cv::Mat& gray, SplitMix64& g, Box& implied) {
  const double rows = gray.rows;
  if (target == HogTarget::kBall) {
    const double r = uniform(g, 3.0, rows / 12.0);
    const double cx = uniform(g, 0, gray.cols);
    const double cy = uniform(g, rows * 0.1, rows);
    implied = {cx - r, cy - r, 2 * r, 2 * r};
  } else {
    const double h = uniform(g, 20.0, rows * 0.9);
    const double fx = uniform(g, 0, gray.cols);
    const double fy = uniform(g, rows * 0.3, rows);
    implied = {fx - 0.27 * h, fy - h, 0.54 * h, h};
  }
  return truth_window(target, hog, implied);
}

bool clear_of(const Box& implied, const LabelledFrame& f) {
  for (const Box& b : f.objects) {
    if (overlap(implied, b) > 0.3) return false;
  }
  for (const Box& b : f.ignore) {
    if (overlap(implied, b) > 0.3) return false;
  }
  return true;
}

class Builder {
 public:
  explicit Builder(const HogParams& hog) : hog_(hog), extractor_(hog) { m.length = hog.feature_length(); }
  void add(const std::vector<std::uint8_t>& patch, int label, bool validation) {
    const std::size_t at = m.features.size();
    m.features.resize(at + static_cast<std::size_t>(m.length));
    (void)extractor_.compute(patch, std::span<float>(m.features.data() + at, static_cast<std::size_t>(m.length)));
    m.labels.push_back(label);
    m.validation.push_back(validation);
  }
  std::vector<float> features(const std::vector<std::uint8_t>& patch) {
    std::vector<float> f(static_cast<std::size_t>(m.length));
    (void)extractor_.compute(patch, f);
    return f;
  }
  SampleMatrix m;

 private:
  HogParams hog_;
  HogExtractor extractor_;
};

struct Fit {
  std::vector<float> weights;
  double bias = 0.0;
  double sign = 1.0;
  cv::Ptr<cv::ml::SVM> svm;
};

Fit fit_svm(const SampleMatrix& m, double c) {
  std::vector<int> rows;
  for (int i = 0; i < m.rows(); ++i) {
    if (!m.validation[static_cast<std::size_t>(i)]) rows.push_back(i);
  }
  cv::Mat x(static_cast<int>(rows.size()), m.length, CV_32F);
  cv::Mat y(static_cast<int>(rows.size()), 1, CV_32S);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const auto src = m.row(rows[r]);
    std::copy(src.begin(), src.end(), x.ptr<float>(static_cast<int>(r)));
    y.at<int>(static_cast<int>(r)) = m.labels[static_cast<std::size_t>(rows[r])];
  }
  Fit fit;
  fit.svm = cv::ml::SVM::create();
  fit.svm->setType(cv::ml::SVM::C_SVC);
  fit.svm->setKernel(cv::ml::SVM::LINEAR);
  fit.svm->setC(c);
  fit.svm->setTermCriteria(cv::TermCriteria(cv::TermCriteria::MAX_ITER + cv::TermCriteria::EPS, 100000, 1e-6));
  if (!fit.svm->train(x, cv::ml::ROW_SAMPLE, y)) throw std::runtime_error("OpenCV's SVM training failed");
  const cv::Mat sv = fit.svm->getSupportVectors();
  cv::Mat alpha, index;
  const double rho = fit.svm->getDecisionFunction(0, alpha, index);
  alpha.convertTo(alpha, CV_64F);
  std::vector<double> w(static_cast<std::size_t>(m.length), 0.0);
  for (int k = 0; k < index.cols * index.rows; ++k) {
    const int s = index.at<int>(k);
    for (int j = 0; j < m.length; ++j) w[static_cast<std::size_t>(j)] += alpha.at<double>(k) * static_cast<double>(sv.at<float>(s, j));
  }
  // OpenCV's raw output is w·x − rho and is positive for its first (smaller) class label; find
  // which way round this build has it from a sample it classifies with a clear margin.
  fit.sign = 1.0;
  for (int r = 0; r < x.rows; ++r) {
    const float raw = fit.svm->predict(x.row(r), cv::noArray(), cv::ml::StatModel::RAW_OUTPUT);
    if (std::abs(raw) < 1e-3f) continue;
    const float label = fit.svm->predict(x.row(r));
    fit.sign = (raw > 0) == (label > 0) ? 1.0 : -1.0;
    break;
  }
  fit.weights.resize(w.size());
  for (std::size_t j = 0; j < w.size(); ++j) fit.weights[j] = static_cast<float>(fit.sign * w[j]);
  fit.bias = -fit.sign * rho;
  return fit;
}

double score_of(const Fit& fit, std::span<const float> f) {
  double s = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) s += static_cast<double>(fit.weights[i]) * static_cast<double>(f[i]);
  return s + fit.bias;
}

Metrics measure(const SampleMatrix& m, const Fit& fit, double threshold, bool validation) {
  Metrics r;
  for (int i = 0; i < m.rows(); ++i) {
    if (m.validation[static_cast<std::size_t>(i)] != validation) continue;
    const bool predicted = score_of(fit, m.row(i)) >= threshold;
    const bool truth = m.labels[static_cast<std::size_t>(i)] > 0;
    (predicted ? (truth ? r.tp : r.fp) : (truth ? r.fn : r.tn))++;
  }
  return r;
}

// The threshold with the highest validation recall at precision ≥ target (the F1-best one when
// none reaches it); `reached` says which.
double choose_threshold(const SampleMatrix& m, const Fit& fit, double target, bool& reached) {
  std::vector<std::pair<double, bool>> scored;
  for (int i = 0; i < m.rows(); ++i) {
    if (!m.validation[static_cast<std::size_t>(i)]) continue;
    scored.emplace_back(score_of(fit, m.row(i)), m.labels[static_cast<std::size_t>(i)] > 0);
  }
  std::sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  int positives = 0;
  for (const auto& s : scored) positives += s.second ? 1 : 0;
  reached = false;
  if (positives == 0 || scored.empty()) return 0.0;
  double best_t = 0.0, best_recall = -1.0, best_f1 = -1.0, f1_t = 0.0;
  int tp = 0, fp = 0;
  for (std::size_t i = 0; i < scored.size(); ++i) {
    (scored[i].second ? tp : fp)++;
    if (i + 1 < scored.size() && scored[i + 1].first == scored[i].first) continue;
    const double precision = static_cast<double>(tp) / (tp + fp);
    const double recall = static_cast<double>(tp) / positives;
    // Half way down to the next lower score: the same validation counts, with a margin.
    const double t = i + 1 < scored.size() ? 0.5 * (scored[i].first + scored[i + 1].first) : scored[i].first;
    if (precision >= target && recall > best_recall) {
      best_recall = recall;
      best_t = t;
    }
    const double f1 = 2 * precision * recall / (precision + recall);
    if (f1 > best_f1) {
      best_f1 = f1;
      f1_t = t;
    }
  }
  reached = best_recall >= 0.0;
  return reached ? best_t : f1_t;
}

}  // namespace

namespace {

// A proposal's label by the evaluation's rules: a ball's centre within max(half its radius,
// 4 px) of a true ball's; a robot's foot point within max(half the box's width, 4 px) of a true
// robot's (the middle of its box's bottom edge). +1 on a true object, −1 clear of every object and
// hidden object, 0 (left out) in between.
int proposal_label(HogTarget target, const Proposal& p, const LabelledFrame& f) {
  int label = -1;
  const auto near = [&](const Box& o, bool counts) {
    const bool ball = target == HogTarget::kBall;
    const double cx = o.x + 0.5 * o.w;
    const double cy = ball ? o.y + 0.5 * o.h : o.y + o.h;
    const double reach = ball ? 0.5 * (0.25 * (o.w + o.h)) : 0.5 * o.w;
    const double d = std::hypot(p.at.u - cx, p.at.v - cy);
    if (counts && d <= std::max(reach, 4.0)) return 1;
    const double clear = ball ? 0.25 * (o.w + o.h) + 2.0 * p.size : o.w;
    return d < clear ? 0 : -1;
  };
  for (const Box& o : f.objects) {
    const int l = near(o, true);
    if (l == 1) return 1;
    if (l == 0) label = 0;
  }
  for (const Box& o : f.ignore) {
    if (near(o, false) == 0) label = 0;
  }
  return label;
}

}  // namespace

bool held_out(std::uint64_t seed, std::uint64_t index, double share) {
  SplitMix64 g = SplitMix64::for_frame(seed ^ 0x5A11D47E0ULL, index);
  return static_cast<double>(g.below(1000000)) < share * 1e6;
}

TrainResult train_hog(const std::vector<LabelledFrame>& frames, const PatchSet& patches, const TrainConfig& config) {
  const HogParams hog = params_for(config.target);
  Builder b(hog);
  TrainResult out{HogSvm(config.target, hog, std::vector<float>(static_cast<std::size_t>(hog.feature_length()), 0.0f), 0, 0),
                  {}, {}, 0, 0, 0, 0, 0, true, nullptr, 1.0, {}, 0, 0};
  std::vector<std::uint8_t> patch;
  std::vector<bool> frame_validation(frames.size());
  for (std::size_t fi = 0; fi < frames.size(); ++fi) {
    const LabelledFrame& f = frames[fi];
    const bool val = held_out(config.seed, fi, config.validation_share);
    frame_validation[fi] = val;
    SplitMix64 g = SplitMix64::for_frame(config.seed, fi);
    for (const Box& obj : f.objects) {
      for (int k = 0; k < std::max(1, config.jitter); ++k) {
        WindowPlacement w = truth_window(config.target, hog, obj);
        if (k > 0) {  // jittered copies: the detector's candidates are not perfectly centred
          const double grow = uniform(g, 0.9, 1.1);
          const double side_x = w.scale * hog.window_width, side_y = w.scale * hog.window_height;
          const double cx = w.left + 0.5 * side_x + uniform(g, -0.08, 0.08) * side_x;
          const double cy = w.top + 0.5 * side_y + uniform(g, -0.08, 0.08) * side_y;
          w.scale *= grow;
          w.left = cx - 0.5 * side_x * grow;
          w.top = cy - 0.5 * side_y * grow;
        }
        cut_patch(f.gray, w, hog, patch);
        b.add(patch, +1, val);
      }
    }
    // The detector's own proposals (proposals.hpp), labelled by the truth: what the classifier
    // meets at run time, in training and in the validation that sets the threshold.
    for (const Proposal& p : f.proposals) {
      const int label = proposal_label(config.target, p, f);
      if (label == 0) continue;
      cut_patch(f.gray, p.window, hog, patch);
      b.add(patch, label, val);
      (label > 0 ? out.proposal_positives : out.proposal_negatives)++;
    }
    for (int k = 0, tries = 0; k < config.negatives_per_frame && tries < 20 * config.negatives_per_frame; ++tries) {
      Box implied;
      const WindowPlacement w = random_window(config.target, hog, f.gray, g, implied);
      if (!clear_of(implied, f)) continue;
      cut_patch(f.gray, w, hog, patch);
      b.add(patch, -1, val);
      ++k;
    }
  }
  for (std::size_t i = 0; i < patches.positives.size(); ++i) {
    b.add(patches.positives[i], +1, held_out(config.seed + 1, i, config.validation_share));
  }
  for (std::size_t i = 0; i < patches.negatives.size(); ++i) {
    b.add(patches.negatives[i], -1, held_out(config.seed + 2, i, config.validation_share));
  }
  int train_pos = 0, train_neg = 0;
  for (int i = 0; i < b.m.rows(); ++i) {
    if (b.m.validation[static_cast<std::size_t>(i)]) continue;
    (b.m.labels[static_cast<std::size_t>(i)] > 0 ? train_pos : train_neg)++;
  }
  if (train_pos == 0) throw ToolError("no positive training samples (no " + std::string(to_string(config.target)) + " in the training frames or pos/ patches)");
  if (train_neg == 0) throw ToolError("no negative training samples");

  Fit fit = fit_svm(b.m, config.c);
  out.log.push_back("round 0: " + std::to_string(train_pos) + " positive and " + std::to_string(train_neg) +
                    " negative training windows");
  out.log.push_back("the detector's proposals (training and validation): " + std::to_string(out.proposal_positives) +
                    " on a true object, " + std::to_string(out.proposal_negatives) + " clear of every object");
  for (int round = 1; round <= config.hard_rounds && !frames.empty(); ++round) {
    // Hard negatives: random windows of the training frames the current model scores as the target.
    int added = 0;
    for (std::size_t fi = 0; fi < frames.size(); ++fi) {
      if (frame_validation[fi]) continue;
      const LabelledFrame& f = frames[fi];
      SplitMix64 g = SplitMix64::for_frame(config.seed + 1000 * static_cast<std::uint64_t>(round), fi);
      int kept = 0;
      for (int k = 0; k < config.hard_tries_per_frame && kept < config.hard_per_frame; ++k) {
        Box implied;
        const WindowPlacement w = random_window(config.target, hog, f.gray, g, implied);
        if (!clear_of(implied, f)) continue;
        cut_patch(f.gray, w, hog, patch);
        if (score_of(fit, b.features(patch)) < 0.0) continue;
        b.add(patch, -1, false);
        ++kept;
      }
      added += kept;
    }
    out.hard_negatives += added;
    out.log.push_back("round " + std::to_string(round) + ": " + std::to_string(added) + " hard negatives added");
    if (added == 0) break;
    fit = fit_svm(b.m, config.c);
  }

  const double threshold = choose_threshold(b.m, fit, config.min_precision, out.precision_reached);
  out.model = HogSvm(config.target, hog, fit.weights, fit.bias, threshold);
  out.training = measure(b.m, fit, threshold, false);
  out.validation = measure(b.m, fit, threshold, true);
  for (int i = 0; i < b.m.rows(); ++i) {
    const bool pos = b.m.labels[static_cast<std::size_t>(i)] > 0;
    if (b.m.validation[static_cast<std::size_t>(i)]) {
      (pos ? out.validation_positives : out.validation_negatives)++;
    } else {
      (pos ? out.positives : out.negatives)++;
    }
  }
  out.svm = fit.svm;
  out.opencv_sign = fit.sign;
  return out;
}

}  // namespace ringlet::vision::train
