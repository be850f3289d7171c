// Localization in the full simulated stack: the SPL field with a referee's pick-up
// ([sim] kidnap), camera, vision and the localization task in lockstep.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <sstream>

#include "firmware_test_support.hpp"
#include "ringlet/firmware/mission_runner.hpp"
#include "ringlet/firmware/stack.hpp"

namespace ringlet::firmware {
namespace {

TEST(LocalizationInTheStack, AKidnapOnTheSplFieldIsReportedAndRecovered) {
  // Picked up at 2 s on the way to the first goal (near (-1.5, -2.2), heading +x) and put down
  // 3.5 m away, facing +x in the own half; 5 s in all: 1.5 s past the recovery's deadline
  // shows the estimate stays good (it recovers in about 0.2 s).
  constexpr double kKidnapS = 2.0;
  auto text = test::with_line(test::shipped_config_text(test::kSplConfig), "timeout_s", "timeout_s = 5");
  text = test::with_line(text, "robot_radius",
                         "robot_radius = 0.25\nkidnap = { at_s = 2.0, x = -2.0, y = 1.0, theta_deg = 90 }");
  const auto cfg = test::parse_as_shipped(text);
  FirmwareStack stack(cfg);
  std::atomic<bool> interrupt{false};
  std::ostringstream log;
  (void)run_mission(stack, cfg.mission.timeout_s, interrupt, log);

  const wb::Localization l = stack.whiteboard().get<wb::Localization>();
  // The pick-up is reported as lost, and the recovery at the new place as a relocalization.
  EXPECT_GT(l.lost_frames, 0U) << "the pick-up is reported lost meanwhile";
  EXPECT_GE(l.relocalizations, 1U) << "the recovery 3.5 m from the dead-reckoned pose is a relocalization";
  const LocalizationScore& score = stack.truth_score()->localization();
  // Never driving on a pose more than 0.5 m wrong for longer than 0.3 s (30 frames).
  EXPECT_LE(score.longest_valid_wrong, 30U);
  // Recovered: the estimate is valid and within 0.5 m from at most 1.5 s after the pick-up on.
  const double last_bad_s = std::chrono::duration<double>(score.last_not_good).count();
  EXPECT_GT(last_bad_s, kKidnapS) << "the pick-up made the estimate wrong or invalid for a while";
  EXPECT_LT(last_bad_s, kKidnapS + 1.5);
  std::printf("kidnap: recovered %.2f s after the pick-up; %llu lost frames, %u relocalizations, longest valid-and-wrong %llu frames\n",
              last_bad_s - kKidnapS, static_cast<unsigned long long>(l.lost_frames), l.relocalizations,
              static_cast<unsigned long long>(score.longest_valid_wrong));
  EXPECT_EQ(stack.telemetry().collisions(), 0U);
}

}  // namespace
}  // namespace ringlet::firmware
