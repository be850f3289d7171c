#pragma once
// Where the ground ends in the image: per column, the first row whose viewing ray points down at
// the ground. The horizon is the image of the ground plane's vanishing line for the camera pose of
// the whole chain (torso tilt, head yaw and pitch: hal::CameraPose::from_body). With an upright
// torso it is a horizontal row; a rolled torso slants it by about the roll angle (positive roll,
// leaning right, raises its right end), so it is computed per column.
#include <span>

#include "ringlet/hal/camera_geometry.hpp"

namespace ringlet::vision {

/// Fills first_row[u] (u < k.width) with the first row at or below the horizon plus `margin_px`
/// rows, clamped to [0, k.height] (k.height: no ground in that column). Returns the minimum over
/// the columns.
int horizon_rows(const hal::CameraIntrinsics& k, const hal::CameraPose& pose, int margin_px, std::span<int> first_row) noexcept;

/// The horizon's image row at column u (may lie outside the image; +inf above when the camera
/// looks straight down). Exposed for tests.
[[nodiscard]] double horizon_v(const hal::CameraIntrinsics& k, const hal::CameraPose& pose, double u) noexcept;

}  // namespace ringlet::vision
