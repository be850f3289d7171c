// The compile-time type list: stable names, ids, versions, and visiting every type.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ringlet/whiteboard/messages.hpp"

namespace ringlet::wb {
namespace {

TEST(WbTypeList, NamesAndIdsAreTheSchemaOnes) {
  const std::vector<std::string> names{"BallBelief", "HeadCommand", "MotionCommand",
                                       "Pose",       "LaserSummary", "FsmStatus",
                                       "FsmControl", "ExecutiveTiming", "Print",
                                       "FieldLines",  "HeadPosture",   "BodyState",    "MissionGoals",
                                       "MissionStatus", "RobotDetections", "LaserScan", "Plan", "ArbiterCommand",
                                       "BridgeHealth", "BoardHealth", "PddlRequest", "PddlReply", "Localization"};
  ASSERT_EQ(kTypeCount, names.size());
  for (std::size_t i = 0; i < kTypeCount; ++i) {
    EXPECT_EQ(kTypes[i].name, names[i]);
    EXPECT_EQ(to_underlying(kTypes[i].id), i + 1);
    // Version 2: HeadPosture gained the torso's tilt, ExecutiveTiming the task table, Plan the map,
    // FieldLines the penalty and centre marks.
    const bool second = names[i] == "HeadPosture" || names[i] == "ExecutiveTiming" || names[i] == "Plan" ||
                        names[i] == "FieldLines";
    EXPECT_EQ(kTypes[i].version, second ? 2 : 1) << names[i];
  }
  static_assert(BallBelief::kId == TypeId{1} && Print::kName == "Print");
  static_assert(kIndexOf<Pose> == 3);
}

TEST(WbTypeList, ForEachTypeVisitsAllInIdOrder) {
  std::vector<std::string> seen;
  for_each_type([&](auto t) {
    using T = typename decltype(t)::type;
    seen.emplace_back(T::kName);
  });
  ASSERT_EQ(seen.size(), kTypeCount);
  for (std::size_t i = 0; i < kTypeCount; ++i) EXPECT_EQ(seen[i], kTypes[i].name);
}

TEST(WbTypeList, FindByNameOrId) {
  ASSERT_TRUE(find_type("FsmStatus").has_value());
  EXPECT_EQ(find_type("FsmStatus")->id, FsmStatus::kId);
  EXPECT_EQ(find_type(TypeId{7})->name, "FsmControl");
  EXPECT_FALSE(find_type("Nope").has_value());
  EXPECT_FALSE(find_type(TypeId{999}).has_value());
}

TEST(WbFixedString, TruncatesComparesAndViews) {
  FixedString<4> s;
  EXPECT_TRUE(s.empty());
  EXPECT_FALSE(s.assign("hello"));
  EXPECT_EQ(s.view(), "hell");
  s = "hi";
  EXPECT_EQ(s, "hi");
  EXPECT_EQ(s, FixedString<4>("hi"));
  EXPECT_EQ(s.size(), 2U);
}

}  // namespace
}  // namespace ringlet::wb
