#include "ringlet/behaviour/plan_execute.hpp"

#include <algorithm>
#include <cmath>

#include "ringlet/hal/portable_math.hpp"

namespace ringlet::behaviour {

bool obstacle_on_leg(std::span<const std::uint16_t> range_mm, double angle_min, double increment,
                     const hal::Pose2& pose, const Waypoint& target, double range, double corridor, double& ox,
                     double& oy) noexcept {
  const double lx = target.x - pose.x, ly = target.y - pose.y;
  const double length = hal::portable_hypot(lx, ly);
  if (length < 1e-6) return false;
  const double ux = lx / length, uy = ly / length;
  const double reach = std::min(range, length);
  double best = reach;
  bool found = false;
  for (std::size_t i = 0; i < range_mm.size(); ++i) {
    if (range_mm[i] == 0) continue;
    const double r = range_mm[i] * 1e-3;
    // theta and the beams turn clockwise from +y (hal/geometry.hpp): a bearing b points at (sin b, cos b).
    const double b = pose.theta + angle_min + static_cast<double>(i) * increment;
    const double px = pose.x + r * std::sin(b), py = pose.y + r * std::cos(b);
    const double along = (px - pose.x) * ux + (py - pose.y) * uy;
    const double across = std::abs((px - pose.x) * uy - (py - pose.y) * ux);
    if (along <= 0.0 || along > best || across > corridor) continue;
    best = along;
    ox = px;
    oy = py;
    found = true;
  }
  return found;
}

std::string_view nth_word(std::string_view text, int n) noexcept {
  std::size_t i = 0;
  for (int k = 0;; ++k) {
    while (i < text.size() && text[i] == ' ') ++i;
    if (i >= text.size()) return {};
    std::size_t j = i;
    while (j < text.size() && text[j] != ' ') ++j;
    if (k == n) return text.substr(i, j - i);
    i = j;
  }
}

}  // namespace ringlet::behaviour
