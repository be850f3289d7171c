// Task table validation: every rule of validate() and the Executive constructor's refusal.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "executive_test_support.hpp"
#include "ringlet/executive/executive.hpp"
#include "ringlet/executive/task_table.hpp"

namespace ringlet::executive::test {
namespace {

ExecutiveConfig config_with_period(Nanos period) {
  ExecutiveConfig c;
  c.period = period;
  return c;
}

// True when some problem contains every one of `needles`.
bool has_problem(const std::vector<std::string>& problems, const std::vector<std::string>& needles) {
  return std::any_of(problems.begin(), problems.end(), [&](const std::string& p) {
    return std::all_of(needles.begin(), needles.end(),
                       [&](const std::string& n) { return p.find(n) != std::string::npos; });
  });
}

std::string dump(const std::vector<std::string>& problems) {
  std::string s;
  for (const auto& p : problems) s += "\n  " + p;
  return s;
}

TEST(TaskTable, ValidTablePasses) {
  const std::vector<TaskSpec> table = {spec("sense", 1, 0, 2ms), spec("plan", 3, 1, 3ms),
                                       spec("log", 10, 5, 1ms, OverrunPolicy::kSkip)};
  const auto problems = validate(ExecutiveConfig{}, table);
  EXPECT_TRUE(problems.empty()) << dump(problems);
}

TEST(TaskTable, EveryBelowOneRefused) {
  const std::vector<TaskSpec> table = {spec("zero", 0, 0, 1ms), spec("negative", -2, 0, 1ms), spec("fine", 1, 0, 1ms)};
  const auto problems = validate(ExecutiveConfig{}, table);
  ASSERT_EQ(problems.size(), 2U) << dump(problems);
  EXPECT_TRUE(has_problem(problems, {"'zero'", "every", "0"})) << dump(problems);
  EXPECT_TRUE(has_problem(problems, {"'negative'", "every", "-2"})) << dump(problems);
}

TEST(TaskTable, PhaseOutOfRangeRefused) {
  const std::vector<TaskSpec> table = {spec("too_late", 3, 3, 1ms), spec("negative", 4, -1, 1ms),
                                       spec("last_ok", 3, 2, 1ms)};
  const auto problems = validate(ExecutiveConfig{}, table);
  ASSERT_EQ(problems.size(), 2U) << dump(problems);
  EXPECT_TRUE(has_problem(problems, {"'too_late'", "phase", "0..2"})) << dump(problems);
  EXPECT_TRUE(has_problem(problems, {"'negative'", "phase", "0..3"})) << dump(problems);
}

TEST(TaskTable, ZeroOrNegativeBudgetRefused) {
  const std::vector<TaskSpec> table = {spec("free", 1, 0, Nanos{0}), spec("negative", 1, 0, Nanos{-5})};
  const auto problems = validate(ExecutiveConfig{}, table);
  ASSERT_EQ(problems.size(), 2U) << dump(problems);
  EXPECT_TRUE(has_problem(problems, {"'free'", "budget must be > 0"})) << dump(problems);
  EXPECT_TRUE(has_problem(problems, {"'negative'", "budget must be > 0"})) << dump(problems);
}

TEST(TaskTable, BudgetAbovePeriodRefusedButEqualAccepted) {
  const auto cfg = config_with_period(10ms);
  const std::vector<TaskSpec> over = {spec("greedy", 2, 0, 10ms + Nanos{1})};
  const auto problems = validate(cfg, over);
  ASSERT_EQ(problems.size(), 1U) << dump(problems);
  EXPECT_TRUE(has_problem(problems, {"'greedy'", "larger than the period"})) << dump(problems);

  const std::vector<TaskSpec> exact = {spec("whole_frame", 1, 0, 10ms)};
  EXPECT_TRUE(validate(cfg, exact).empty());
}

TEST(TaskTable, DuplicateAndEmptyNamesRefused) {
  const std::vector<TaskSpec> table = {spec("twin", 2, 0, 1ms), spec("twin", 2, 1, 1ms), spec("", 1, 0, 1ms)};
  const auto problems = validate(ExecutiveConfig{}, table);
  ASSERT_EQ(problems.size(), 2U) << dump(problems);
  EXPECT_TRUE(has_problem(problems, {"'twin'", "used twice"})) << dump(problems);
  EXPECT_TRUE(has_problem(problems, {"empty name"})) << dump(problems);
}

TEST(TaskTable, EmptyTableRefused) {
  const auto problems = validate(ExecutiveConfig{}, std::vector<TaskSpec>{});
  ASSERT_EQ(problems.size(), 1U) << dump(problems);
  EXPECT_TRUE(has_problem(problems, {"empty"})) << dump(problems);
}

TEST(TaskTable, NonPositivePeriodRefused) {
  const std::vector<TaskSpec> table = {spec("a", 1, 0, 1ms)};
  EXPECT_TRUE(has_problem(validate(config_with_period(Nanos{0}), table), {"period must be > 0"}));
  EXPECT_TRUE(has_problem(validate(config_with_period(-10ms), table), {"period must be > 0"}));
}

TEST(TaskTable, OverloadedFrameRefusedNamingFrameAndTasks) {
  const auto cfg = config_with_period(10ms);
  std::vector<TaskSpec> table = {spec("left", 2, 0, 6ms), spec("right", 2, 0, 6ms)};
  const auto problems = validate(cfg, table);
  ASSERT_EQ(problems.size(), 1U) << dump(problems);  // frame 1 carries nothing: only frame 0 is named
  EXPECT_TRUE(has_problem(problems, {"frame 0 ", "overloaded", "left", "right", "12000 us"})) << dump(problems);

  table[1].phase = 1;  // one per frame now
  const auto moved = validate(cfg, table);
  EXPECT_TRUE(moved.empty()) << dump(moved);
}

TEST(TaskTable, OverloadFoundDeepInTheHyperperiod) {
  // every=3 phase 2 and every=7 phase 6 meet first in frame 20 (mod 21).
  const auto cfg = config_with_period(10ms);
  const std::vector<TaskSpec> table = {spec("base", 1, 0, 2ms), spec("three", 3, 2, 4ms), spec("seven", 7, 6, 5ms)};
  const auto problems = validate(cfg, table);
  ASSERT_EQ(problems.size(), 1U) << dump(problems);
  EXPECT_TRUE(has_problem(problems, {"frame 20 ", "mod 21", "base", "three", "seven"})) << dump(problems);
}

TEST(TaskTable, FrameFilledExactlyToThePeriodAccepted) {
  const std::vector<TaskSpec> table = {spec("a", 1, 0, 4ms), spec("b", 2, 0, 6ms), spec("c", 2, 1, 6ms)};
  EXPECT_TRUE(validate(config_with_period(10ms), table).empty());
}

TEST(TaskTable, Table83HzValid) {
  // 83 Hz: a 12 ms base period (12.048 ms exactly), with a 41.5 Hz pair sharing the frames.
  for (const Nanos period : {Nanos{12ms}, Nanos{12'048'193}}) {
    const std::vector<TaskSpec> table = {spec("sense", 1, 0, 3ms), spec("motion", 1, 0, 2ms),
                                         spec("vision", 2, 0, 6ms), spec("plan", 2, 1, 6ms),
                                         spec("log", 83, 41, 1ms)};
    const auto problems = validate(config_with_period(period), table);
    EXPECT_TRUE(problems.empty()) << "period " << period.count() << " ns:" << dump(problems);
  }
}

TEST(TaskTable, HugeHyperperiodRefused) {
  // Three primes near 1000: their frames only line up after ~9.7e8 frames.
  const std::vector<TaskSpec> table = {spec("p997", 997, 0, 1ms), spec("p991", 991, 0, 1ms), spec("p983", 983, 0, 1ms)};
  const auto problems = validate(ExecutiveConfig{}, table);
  ASSERT_EQ(problems.size(), 1U) << dump(problems);
  EXPECT_TRUE(has_problem(problems, {std::to_string(kMaxHyperperiod), "common multiple"})) << dump(problems);
}

TEST(TaskTable, HyperperiodAtTheLimitAcceptedJustAboveRefused) {
  const std::vector<TaskSpec> at_limit = {spec("slow", static_cast<int>(kMaxHyperperiod), 0, 1ms), spec("fast", 1, 0, 1ms)};
  EXPECT_TRUE(validate(ExecutiveConfig{}, at_limit).empty());
  const std::vector<TaskSpec> above = {spec("slow", static_cast<int>(kMaxHyperperiod), 0, 1ms), spec("odd", 3, 0, 1ms)};
  EXPECT_TRUE(has_problem(validate(ExecutiveConfig{}, above), {"common multiple"}));
}

TEST(TaskTable, OverloadInEveryFrameListsTheFirstProblemsAndCountsTheRest) {
  // 6 + 6 ms in a 10 ms period in each of the 100,000 frames of the hyperperiod: spelling out
  // every frame would be 100,000 lines (17 MB); the first kMaxProblemsListed are enough.
  const std::vector<TaskSpec> table = {spec("left", 1, 0, 6ms), spec("right", 1, 0, 6ms),
                                       spec("slow", static_cast<int>(kMaxHyperperiod), 0, Nanos{1})};
  const auto problems = validate(config_with_period(10ms), table);
  ASSERT_EQ(problems.size(), kMaxProblemsListed + 1) << dump(problems);
  EXPECT_TRUE(has_problem({problems.front()}, {"frame 0 ", "left", "right", "slow"})) << dump(problems);
  EXPECT_TRUE(has_problem({problems[kMaxProblemsListed - 1]}, {"frame 19 "})) << dump(problems);
  EXPECT_EQ(problems.back(), "... and " + std::to_string(kMaxHyperperiod - kMaxProblemsListed) + " more problems");
}

TEST(TaskTable, ManyBadRowsAreBoundedToo) {
  std::vector<TaskSpec> table;
  for (int i = 0; i < 30; ++i) table.push_back(spec("free" + std::to_string(i), 1, 0, Nanos{0}));
  const auto problems = validate(ExecutiveConfig{}, table);
  ASSERT_EQ(problems.size(), kMaxProblemsListed + 1) << dump(problems);
  EXPECT_EQ(problems.back(), "... and 10 more problems");
}

TEST(TaskTable, MoreRowsThanAllowedRefusedBeforeTheOverloadWalk) {
  std::vector<TaskSpec> table;
  for (std::size_t i = 0; i <= kMaxTasks; ++i) table.push_back(spec("t" + std::to_string(i), 1, 0, Nanos{1}));
  const auto problems = validate(ExecutiveConfig{}, table);
  ASSERT_EQ(problems.size(), 1U) << dump(problems);
  EXPECT_TRUE(has_problem(problems, {std::to_string(kMaxTasks + 1) + " rows", "at most " + std::to_string(kMaxTasks)}));
  table.pop_back();
  EXPECT_TRUE(validate(ExecutiveConfig{}, table).empty()) << "exactly kMaxTasks rows are fine";
}

TEST(TaskTable, ListProblemsShowsAtMostTheLimit) {
  std::vector<std::string> many;
  for (int i = 0; i < 25; ++i) many.push_back("p" + std::to_string(i));
  const std::string text = list_problems(many);
  EXPECT_EQ(text.rfind("\n  - p0\n  - p1\n", 0), 0U) << text;
  EXPECT_NE(text.find("\n  - p19\n  - ... and 5 more"), std::string::npos) << text;
  EXPECT_EQ(text.find("p20"), std::string::npos) << text;
  EXPECT_EQ(list_problems(std::vector<std::string>{"only"}), "\n  - only");
}

TEST(TaskTable, PolicyNamesRoundTrip) {
  for (const auto p : {OverrunPolicy::kWarn, OverrunPolicy::kSkip, OverrunPolicy::kDegrade, OverrunPolicy::kFailsafe}) {
    OverrunPolicy parsed = p == OverrunPolicy::kWarn ? OverrunPolicy::kFailsafe : OverrunPolicy::kWarn;
    ASSERT_TRUE(parse_policy(to_string(p), parsed)) << to_string(p);
    EXPECT_EQ(parsed, p);
  }
  OverrunPolicy untouched = OverrunPolicy::kDegrade;
  EXPECT_FALSE(parse_policy("Warn", untouched));
  EXPECT_FALSE(parse_policy("", untouched));
  EXPECT_EQ(untouched, OverrunPolicy::kDegrade);
}

TEST(TaskTable, ExecutiveConstructorThrowsListingEveryProblem) {
  Rig rig;
  rig.add(spec("free", 1, 0, Nanos{0}), 0ms);
  rig.add(spec("twin", 2, 0, 1ms), 0ms);
  rig.add(spec("twin", 2, 1, 1ms), 0ms);
  rig.add(spec("late", 2, 2, 1ms), 0ms);
  try {
    rig.build();
    FAIL() << "an invalid table was accepted";
  } catch (const TableError& e) {
    const auto& problems = e.problems();
    EXPECT_EQ(problems.size(), 3U) << dump(problems);
    EXPECT_TRUE(has_problem(problems, {"'free'", "budget"})) << dump(problems);
    EXPECT_TRUE(has_problem(problems, {"'twin'", "twice"})) << dump(problems);
    EXPECT_TRUE(has_problem(problems, {"'late'", "phase"})) << dump(problems);
    const std::string what = e.what();
    for (const auto& p : problems) EXPECT_NE(what.find(p), std::string::npos) << what;
  }
}

TEST(TaskTable, NullTaskPointerRefused) {
  hal::VirtualClock clock;
  FakeActuators actuators;
  ScriptedTask real(clock, "real", 1ms);
  std::vector<TaskBinding> bindings = {TaskBinding{spec("real", 1, 0, 2ms), &real},
                                       TaskBinding{spec("ghost", 1, 0, 2ms), nullptr}};
  try {
    Executive exec(ExecutiveConfig{}, bindings, clock, clock, actuators);
    FAIL() << "a null task was accepted";
  } catch (const TableError& e) {
    ASSERT_EQ(e.problems().size(), 1U) << dump(e.problems());
    EXPECT_TRUE(has_problem(e.problems(), {"'ghost'", "no implementation"})) << dump(e.problems());
  }
  bindings[1].task = &real;  // the same object bound twice is allowed (two table entries)
  EXPECT_NO_THROW(Executive(ExecutiveConfig{}, bindings, clock, clock, actuators));
}

}  // namespace
}  // namespace ringlet::executive::test
