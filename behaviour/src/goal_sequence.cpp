#include "ringlet/behaviour/goal_sequence.hpp"

#include <algorithm>
#include <cmath>

#include "ringlet/hal/portable_math.hpp"

namespace ringlet::behaviour {

std::size_t goals_reached_at(std::span<const double> x, std::span<const double> y, std::size_t reached,
                             const hal::Pose2& pose, double tolerance) noexcept {
  const std::size_t count = std::min(x.size(), y.size());
  while (reached < count && hal::portable_hypot(x[reached] - pose.x, y[reached] - pose.y) <= tolerance) ++reached;
  return reached;
}

}  // namespace ringlet::behaviour
