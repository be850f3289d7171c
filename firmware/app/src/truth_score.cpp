#include "ringlet/firmware/truth_score.hpp"

#include <algorithm>
#include <cmath>

namespace ringlet::firmware {

void TruthScore::frame_done(std::uint64_t /*frame*/, hal::Nanos frame_start) noexcept {
  const auto ball = truth_.ball_in_robot_frame();
  if (!ball) return;
  const double wanted = std::atan2(ball->y, ball->x);
  if (frame_start < std::chrono::seconds{1} || std::abs(wanted) > HeadTracking::kNeckLimit) return;
  const double error = std::abs(hal::wrap_angle(board_.get<wb::HeadPosture>().yaw - wanted));
  ++head_.frames;
  if (error <= HeadTracking::kOnTarget) ++head_.on_target;
  head_.sum_error += error;
  head_.max_error = std::max(head_.max_error, error);
}

}  // namespace ringlet::firmware
