#include "ringlet/firmware/truth_score.hpp"

#include <algorithm>
#include <cmath>

#include "ringlet/hal/portable_math.hpp"

namespace ringlet::firmware {

namespace {

template <std::size_t N>
double percentile95(const std::array<std::uint32_t, N>& bins, std::uint64_t total, double bin) noexcept {
  const std::uint64_t wanted = (total * 95 + 99) / 100;
  std::uint64_t seen = 0;
  for (std::size_t i = 0; i < N; ++i) {
    seen += bins[i];
    if (seen >= wanted) return (static_cast<double>(i) + 1.0) * bin;  // the bin's upper edge
  }
  return static_cast<double>(N) * bin;
}

}  // namespace

double LocalizationScore::p95_position() const noexcept { return percentile95(position, frames, kPositionBin); }
double LocalizationScore::p95_heading_deg() const noexcept { return percentile95(heading, frames, kHeadingBin); }

void TruthScore::frame_done(std::uint64_t frame, hal::Nanos frame_start) noexcept {
  if (board_.generation<wb::Localization>() > 0) {
    if (const auto pose = truth_.robot_pose()) {
      if (telemetry_ != nullptr && telemetry_->localization() != nullptr && frame % every_ == 0) {
        telemetry_->record_true_pose(*pose);
      }
      const wb::Localization l = board_.get<wb::Localization>();
      const double e = hal::portable_hypot(l.x - pose->x, l.y - pose->y);
      const double h = hal::rad_to_deg(std::abs(hal::wrap_angle(l.theta - pose->theta)));
      ++loc_.frames;
      loc_.sum_position += e;
      loc_.sum_heading_deg += h;
      loc_.max_position = std::max(loc_.max_position, e);
      loc_.position[std::min(loc_.position.size() - 1, static_cast<std::size_t>(e / LocalizationScore::kPositionBin))]++;
      loc_.heading[std::min(loc_.heading.size() - 1, static_cast<std::size_t>(h / LocalizationScore::kHeadingBin))]++;
      const bool valid = board_.get<wb::Pose>().valid;
      if (valid) {
        ++loc_.valid_frames;
        loc_.sum_valid_position += e;
      }
      if (valid && e > LocalizationScore::kWrong) {
        ++loc_.valid_wrong_frames;
        loc_.longest_valid_wrong = std::max(loc_.longest_valid_wrong, ++loc_.current_valid_wrong);
      } else {
        loc_.current_valid_wrong = 0;
      }
      if (!valid || e > LocalizationScore::kWrong) loc_.last_not_good = frame_start;
    }
  }
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
