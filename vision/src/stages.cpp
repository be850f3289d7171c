#include "ringlet/vision/stages.hpp"

namespace ringlet::vision {

std::string_view stage_name(Stage stage) noexcept {
  switch (stage) {
    case Stage::kHorizon: return "horizon";
    case Stage::kClassify: return "classify";
    case Stage::kBall: return "ball";
    case Stage::kScan: return "scan";
    case Stage::kRansac: return "ransac";
    case Stage::kCircle: return "circle";
    case Stage::kRobots: return "robots";
    case Stage::kCount: break;  // no default: a stage added without a name here is a -Wswitch error
  }
  return "?";
}

std::array<double, kStageCount> host_cost_by_stage(const HostCost& c) noexcept {
  std::array<double, kStageCount> by_stage{};
  const auto at = [&by_stage](Stage s) -> double& { return by_stage[static_cast<std::size_t>(s)]; };
  at(Stage::kHorizon) = c.fixed;
  at(Stage::kClassify) = c.colour_samples + c.colour_rebuilds + c.classified_pixels;
  at(Stage::kBall) = c.ball_samples + c.ball_windows;
  at(Stage::kScan) = c.scanned_pixels + c.candidates;
  at(Stage::kRansac) = c.point_tests;
  at(Stage::kCircle) = c.circle_tests;
  at(Stage::kRobots) = c.robot_samples + c.robot_windows;
  return by_stage;
}

}  // namespace ringlet::vision
