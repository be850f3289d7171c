// The DDS form of the whiteboard's types: ROS 2-style topic names, a lossless round trip for every
// field kind (scalars, enums, bounded strings, arrays), and validation of what arrives from the
// network (an unknown enum value, an unterminated string, a NaN are refused, the message untouched).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>

#include "ringlet/remote/topics.hpp"

namespace ringlet::remote {
namespace {

TEST(RemoteTopics, NamesFollowRos2TopicNaming) {
  EXPECT_EQ(topic_name("FsmStatus"), "rt/ringlet/fsm_status");
  EXPECT_EQ(topic_name("ArbiterCommand"), "rt/ringlet/arbiter_command");
  EXPECT_EQ(topic_name("Pose"), "rt/ringlet/pose");
}

TEST(RemoteTopics, EveryFieldKindSurvivesTheRoundTrip) {
  wb::FsmStatus status;
  status.machine = "BallTracker";
  status.state = "Track";
  status.previous = "Search";
  status.ringlets = 123456789012ULL;
  status.suspended = true;
  DdsType<wb::FsmStatus>::Sample s{};
  to_sample(status, 7, 42, s);
  EXPECT_EQ(s.robot, 7);
  EXPECT_EQ(s.generation, 42U);
  EXPECT_STREQ(s.machine, "BallTracker");
  wb::FsmStatus back;
  ASSERT_TRUE(from_sample(s, back));
  EXPECT_EQ(back, status);

  wb::Plan plan;
  plan.status = wb::kUnreachable;
  plan.goal_x = -1.25;
  plan.path_count = 3;
  plan.path_x = {};
  plan.path_x[2] = 4.5;
  plan.new_cells[255] = 0xFFFFFFFFU;
  plan.expansions = std::numeric_limits<std::uint64_t>::max();
  DdsType<wb::Plan>::Sample p{};
  to_sample(plan, 1, 1, p);
  EXPECT_EQ(static_cast<int>(p.status), static_cast<int>(wb::kUnreachable));
  wb::Plan plan_back;
  ASSERT_TRUE(from_sample(p, plan_back));
  EXPECT_EQ(plan_back, plan);

  // A string of the full capacity (32 chars) keeps all 32.
  wb::FsmControl control;
  const std::string long_name(32, 'x');
  control.machine = std::string_view{long_name};
  control.command = wb::kRestart;
  DdsType<wb::FsmControl>::Sample c{};
  to_sample(control, 0, 1, c);
  wb::FsmControl control_back;
  ASSERT_TRUE(from_sample(c, control_back));
  EXPECT_EQ(control_back, control);
}

TEST(RemoteTopics, ValuesWithoutWhiteboardMeaningAreRefusedAndTheMessageIsUntouched) {
  wb::FsmControl control;
  control.machine = "Safety";
  control.command = wb::kSuspend;
  DdsType<wb::FsmControl>::Sample good{};
  to_sample(control, 0, 1, good);

  const wb::FsmControl before = [] {
    wb::FsmControl m;
    m.machine = "untouched";
    return m;
  }();
  {  // an enum value the schema does not have
    auto bad = good;
    const int raw = 17;  // as a peer's own (or a hostile) sample could carry it
    static_assert(sizeof bad.command == sizeof raw);
    std::memcpy(&bad.command, &raw, sizeof raw);
    wb::FsmControl out = before;
    EXPECT_FALSE(from_sample(bad, out));
    EXPECT_EQ(out, before);
  }
  {  // a string that fills its buffer without a terminator
    auto bad = good;
    std::memset(bad.machine, 'a', sizeof bad.machine);
    wb::FsmControl out = before;
    EXPECT_FALSE(from_sample(bad, out));
    EXPECT_EQ(out, before);
  }
  {  // not a number
    wb::Pose pose;
    DdsType<wb::Pose>::Sample s{};
    to_sample(pose, 0, 1, s);
    s.x = std::numeric_limits<double>::quiet_NaN();
    wb::Pose out;
    out.y = 3.0;
    EXPECT_FALSE(from_sample(s, out));
    EXPECT_EQ(out.y, 3.0);
  }
}

}  // namespace
}  // namespace ringlet::remote
