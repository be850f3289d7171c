#pragma once
// What a camera at a known pose would report of the field, for tests and benchmarks of the
// filter without rendering: the visible parts of every field line inside a horizontal field of
// view and a range, as robot-frame segments with seeded endpoint noise, and the centre circle's
// centre when enough of the circle is in view. Optionally false segments (a robot's legs) and
// dropped ones, as vision has (line F1 about 0.7 on the rendered field).
#include <cstdint>

#include "ringlet/hal/geometry.hpp"
#include "ringlet/hal/splitmix64.hpp"
#include "ringlet/localization/field_model.hpp"
#include "ringlet/localization/observations.hpp"

namespace ringlet::localization {

struct ViewParams {
  double head_yaw = 0.0;          // rad, left positive
  double half_fov = 0.5;          // rad (57° / 2)
  double min_range = 0.4;         // m: the camera's footprint starts here
  double max_range = 4.0;         // m: beyond, lines are too thin to find
  double noise = 0.03;            // m σ of an endpoint, plus
  double noise_per_m = 0.02;      //   this per metre of range
  double drop = 0.0;              // chance a segment goes unreported
  double false_line = 0.0;        // chance of one false segment per view
};

/// The view from `truth`; noise from `rng`.
[[nodiscard]] Observations synthetic_view(const FieldModel& field, const hal::Pose2& truth, const ViewParams& view,
                                          hal::SplitMix64& rng) noexcept;

}  // namespace ringlet::localization
