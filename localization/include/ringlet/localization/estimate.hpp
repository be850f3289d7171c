#pragma once
// What the localization believes: the pose of the heaviest hypothesis with its covariance, how
// much it can be relied on, and what it cannot tell apart.
#include <Eigen/Core>

#include "ringlet/hal/geometry.hpp"

namespace ringlet::localization {

struct Estimate {
  hal::Pose2 pose{};             // the main hypothesis: weighted mean of its cluster
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  // of (x, y, θ) over that cluster (m², rad²)
  double share = 0.0;            // weight in the main cluster (0..1)
  hal::Pose2 mirror{};           // the point mirror of pose: same lines, other half
  double mirror_share = 0.0;     // weight near the mirror
  double quality = 0.0;          // the pose's fit to the observations, smoothed (1 perfect)
  double confidence = 0.0;       // share · how well it fits · how tight it is (0..1)
  bool initialised = false;
  bool lost = true;              // the estimate does not explain what the robot sees, or is too loose
  bool ambiguous = false;        // the mirror hypothesis is as good: which half is unknown

  [[nodiscard]] double sigma_xy() const noexcept;     // sqrt of the larger position variance
  [[nodiscard]] double sigma_theta() const noexcept;
  /// Usable for driving: initialised, not lost, not ambiguous.
  [[nodiscard]] bool reliable() const noexcept { return initialised && !lost && !ambiguous; }
};

}  // namespace ringlet::localization
