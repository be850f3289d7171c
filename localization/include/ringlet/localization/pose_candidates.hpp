#pragma once
// Sensor resetting (Lenser and Veloso 2000): poses that explain one observation by themselves,
// for the filter to inject when its particles stopped explaining what the robot sees (a kidnap,
// an unknown start). From the centre circle: the pose that puts the observed centre on the centre
// spot, its heading from a line through the circle (the centre line) when one was seen, else
// drawn. From a segment alone: the pose that lays it on a field line drawn at random, at a random
// place along that line. Every candidate comes with its point mirror (−x, −y, θ + π), which
// explains the same lines on the point-symmetric field: the filter must never lose that mode by
// construction, only by evidence.
#include <cstddef>
#include <span>

#include "ringlet/hal/geometry.hpp"
#include "ringlet/hal/splitmix64.hpp"
#include "ringlet/localization/field_model.hpp"
#include "ringlet/localization/observation_model.hpp"

namespace ringlet::localization {

/// The point mirror of a pose about the centre spot.
[[nodiscard]] inline hal::Pose2 mirrored(const hal::Pose2& p) noexcept {
  return {-p.x, -p.y, hal::wrap_angle(p.theta + 3.141592653589793)};
}

/// A pose drawn uniformly on the carpet; x_sign > 0 (< 0): only where x ≥ 0 (≤ 0); 0: anywhere.
[[nodiscard]] hal::Pose2 uniform_pose(const FieldModel& field, hal::SplitMix64& rng, double x_sign = 0.0) noexcept;

/// Fills `out` with up to out.size() candidates (an even count: pairs of mirrors) and returns how
/// many. With no observation at all the candidates are uniform on the carpet.
std::size_t pose_candidates(const PreparedObservations& obs, const FieldModel& field, hal::SplitMix64& rng,
                            std::span<hal::Pose2> out) noexcept;

}  // namespace ringlet::localization
