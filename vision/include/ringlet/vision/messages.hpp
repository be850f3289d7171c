#pragma once
// A pipeline result as the whiteboard messages the rest of the controller reads: FieldLines, the
// detected BallBelief (simulated = false) and RobotDetections.
#include "ringlet/vision/pipeline.hpp"
#include "ringlet/whiteboard/messages.hpp"

namespace ringlet::vision {

[[nodiscard]] wb::FieldLines to_field_lines(const VisionResult& result) noexcept;
/// Visible only when the ball was seen and its ground position is known.
[[nodiscard]] wb::BallBelief to_ball_belief(const VisionResult& result) noexcept;
/// The robots the frame showed (foot points on the ground), verified or not.
[[nodiscard]] wb::RobotDetections to_robot_detections(const VisionResult& result) noexcept;

}  // namespace ringlet::vision
