#include "mark_score.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

namespace ringlet::vision::evaluate {

CircleCounts score_marks(std::span<const hal::RobotPoint> detected, std::span<const TruthMark> truth,
                         const MarkMatchParams& p) {
  CircleCounts c;
  for (const TruthMark& t : truth) c.truths += t.longest_bar_px >= p.min_bar_px ? 1U : 0U;
  // Every pair within the tolerance, nearest first; each detection and each cross used once.
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
  for (std::size_t d = 0; d < detected.size(); ++d) {
    for (std::size_t t = 0; t < truth.size(); ++t) {
      const double e = std::hypot(detected[d].x - truth[t].centre.x, detected[d].y - truth[t].centre.y);
      if (e <= p.max_centre_error_m) pairs.emplace_back(e, d, t);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> detection_used(detected.size(), false), cross_used(truth.size(), false);
  for (const auto& [e, d, t] : pairs) {
    if (detection_used[d] || cross_used[t]) continue;
    detection_used[d] = true;
    cross_used[t] = true;
    if (truth[t].longest_bar_px < p.min_bar_px) continue;  // don't care: neither right nor wrong
    ++c.detections;
    ++c.true_positives;
    ++c.recalled;
    c.centre_error_sum_m += e;
  }
  for (std::size_t d = 0; d < detected.size(); ++d) c.detections += detection_used[d] ? 0U : 1U;  // matched nothing
  return c;
}

}  // namespace ringlet::vision::evaluate
