#include "ringlet/vision/horizon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ringlet::vision {

// A pixel's ray has robot-frame height component z(u, v) = a·(u − cx)/fx + b·(v − cy)/fy + c with
// (a, b, c) the z components of the camera's right, down and forward axes; the horizon is z = 0
// and the ground lies where z < 0.
double horizon_v(const hal::CameraIntrinsics& k, const hal::CameraPose& pose, double u) noexcept {
  const double a = pose.axes[0].z;
  const double b = pose.axes[1].z;
  const double c = pose.axes[2].z;
  if (std::abs(b) < 1e-12) return -std::numeric_limits<double>::infinity();
  return k.cy - k.fy * (c + a * (u - k.cx) / k.fx) / b;
}

int horizon_rows(const hal::CameraIntrinsics& k, const hal::CameraPose& pose, int margin_px, std::span<int> first_row) noexcept {
  const double b = pose.axes[1].z;
  int lowest = k.height;
  const std::size_t n = std::min(first_row.size(), static_cast<std::size_t>(std::max(k.width, 0)));
  for (std::size_t i = 0; i < n; ++i) {
    const double u = static_cast<double>(i) + 0.5;
    int row = 0;
    if (b < -1e-12) {
      // Normal case (image "down" points down in the world): ground below the horizon. A row is
      // ground when its pixel centre v + 0.5 lies below the horizon.
      const double hv = horizon_v(k, pose, u);
      const double r = std::floor(hv - 0.5) + 1.0 + static_cast<double>(margin_px);
      row = static_cast<int>(std::clamp(r, 0.0, static_cast<double>(k.height)));
    } else if (b > 1e-12) {
      row = k.height;  // camera upside down: not a posture this head can take; no ground assumed
    } else {
      // Looking straight down: the whole column is ground when the forward axis points down.
      row = pose.axes[2].z < 0.0 ? 0 : k.height;
    }
    first_row[i] = row;
    lowest = std::min(lowest, row);
  }
  return lowest;
}

}  // namespace ringlet::vision
