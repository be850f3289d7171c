#pragma once
// A pipeline result as the whiteboard messages the rest of the controller reads: FieldLines and
// the detected BallBelief (simulated = false).
#include "ringlet/vision/pipeline.hpp"
#include "ringlet/whiteboard/messages.hpp"

namespace ringlet::vision {

[[nodiscard]] wb::FieldLines to_field_lines(const VisionResult& result) noexcept;
/// Visible only when the ball was seen and its ground position is known.
[[nodiscard]] wb::BallBelief to_ball_belief(const VisionResult& result) noexcept;

}  // namespace ringlet::vision
