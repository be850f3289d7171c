// The timing report: the terminal table, the JSON and the event descriptions carry the counts.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "executive_test_support.hpp"
#include "ringlet/executive/report.hpp"

namespace ringlet::executive::test {
namespace {

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::string line_with(const std::string& text, const std::string& needle) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.find(needle) != std::string::npos) return line;
  }
  return {};
}

// sense: clean. planner: skip policy, overruns at frames 2 and 6 -> 2 overruns, 2 skipped.
// vision: overruns in frame 5 by 25 ms -> a frame overrun and 2 slips (frames 6, 7).
struct Scenario {
  Rig rig;
  Scenario() {
    rig.add(spec("sense", 1, 0, 1ms), 500us);
    rig.add(spec("planner", 2, 0, 2ms, OverrunPolicy::kSkip), 1ms).cost_in_frame(2, 3ms).cost_in_frame(10, 3ms);
    rig.add(spec("vision", 4, 1, 4ms, OverrunPolicy::kFailsafe), 2ms).cost_in_frame(5, 25ms);
    rig.build().run(20);
  }
  Executive& exec() { return *rig.exec; }
};

TEST(ExecutiveReport, ScenarioCountsAreWhatTheReportShouldShow) {
  Scenario s;
  const auto stats = s.exec().task_stats();
  // planner: frames 0,2,4(skipped),6(lost to the slip),8,10,12(skipped),14,16,18.
  EXPECT_EQ(stats[1].overruns, 2U);
  EXPECT_EQ(stats[1].skipped, 3U);
  EXPECT_EQ(stats[2].overruns, 1U);
  EXPECT_EQ(s.exec().frame_stats().slips, 2U);
}

TEST(ExecutiveReport, TableShowsEveryTaskWithItsOverrunsAndSkips) {
  Scenario s;
  std::ostringstream out;
  print_timing_table(out, s.exec());
  const std::string text = out.str();

  const auto header = words(line_with(text, "TASK"));
  ASSERT_GE(header.size(), 14U) << text;
  std::size_t ovr = 0;
  std::size_t skip = 0;
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == "OVR") ovr = i;
    if (header[i] == "SKIP") skip = i;
  }
  ASSERT_NE(ovr, 0U) << text;
  ASSERT_NE(skip, 0U) << text;

  const auto stats = s.exec().task_stats();
  const auto tasks = s.exec().tasks();
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    const auto row = words(line_with(text, " " + tasks[i].spec.name + " "));
    ASSERT_GT(row.size(), skip) << "no row for " << tasks[i].spec.name << " in\n" << text;
    EXPECT_EQ(row[1], tasks[i].spec.name);
    EXPECT_EQ(row[ovr], std::to_string(stats[i].overruns)) << text;
    EXPECT_EQ(row[skip], std::to_string(stats[i].skipped)) << text;
  }
  EXPECT_NE(text.find("skip"), std::string::npos);
  EXPECT_NE(text.find("failsafe"), std::string::npos);
  EXPECT_NE(text.find("frame-overruns 1"), std::string::npos) << text;
  EXPECT_NE(text.find("slips 2"), std::string::npos) << text;
  EXPECT_NE(text.find("frames 18"), std::string::npos) << text;
}

TEST(ExecutiveReport, JsonCarriesTheCounts) {
  Scenario s;
  const auto j = timing_json(s.exec());
  EXPECT_DOUBLE_EQ(j.at("period_us").get<double>(), 10000.0);
  EXPECT_EQ(j.at("budgets_judged_on").get<std::string>(), "wall");
  const auto& tasks = j.at("tasks");
  ASSERT_EQ(tasks.size(), 3U);
  const auto stats = s.exec().task_stats();
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& t = tasks.at(i);
    EXPECT_EQ(t.at("order").get<std::size_t>(), i);
    EXPECT_EQ(t.at("name").get<std::string>(), s.exec().tasks()[i].spec.name);
    EXPECT_EQ(t.at("runs").get<std::uint64_t>(), stats[i].runs);
    EXPECT_EQ(t.at("overruns").get<std::uint64_t>(), stats[i].overruns);
    EXPECT_EQ(t.at("skipped").get<std::uint64_t>(), stats[i].skipped);
    for (const char* key : {"min_us", "mean_us", "p50_us", "p99_us", "p999_us", "max_us"}) {
      EXPECT_TRUE(t.at("wall").contains(key)) << key;
      EXPECT_TRUE(t.at("cpu").contains(key)) << key;
    }
  }
  EXPECT_EQ(tasks.at(1).at("policy").get<std::string>(), "skip");
  EXPECT_EQ(tasks.at(1).at("overruns").get<std::uint64_t>(), 2U);
  EXPECT_EQ(tasks.at(1).at("skipped").get<std::uint64_t>(), 3U);
  EXPECT_DOUBLE_EQ(tasks.at(1).at("budget_us").get<double>(), 2000.0);
  EXPECT_DOUBLE_EQ(tasks.at(1).at("rate_hz").get<double>(), 50.0);
  EXPECT_DOUBLE_EQ(tasks.at(2).at("wall").at("max_us").get<double>(), 25000.0);

  const auto& f = j.at("frames");
  EXPECT_EQ(f.at("executed").get<std::uint64_t>(), 18U);
  EXPECT_EQ(f.at("frame_overruns").get<std::uint64_t>(), 1U);
  EXPECT_EQ(f.at("slips").get<std::uint64_t>(), 2U);
  EXPECT_TRUE(j.at("failsafe").get<bool>());
  EXPECT_EQ(j.at("failsafe_task").get<std::string>(), "vision");
}

TEST(ExecutiveReport, JsonWithoutFailsafeHasNullTask) {
  Rig rig;
  rig.add(spec("calm", 1, 0, 1ms), 500us);
  ExecutiveConfig cfg;
  cfg.overrun_on_cpu_time = true;
  rig.build(cfg).run(3);
  const auto j = timing_json(*rig.exec);
  EXPECT_FALSE(j.at("failsafe").get<bool>());
  EXPECT_TRUE(j.at("failsafe_task").is_null());
  EXPECT_EQ(j.at("budgets_judged_on").get<std::string>(), "cpu");
  EXPECT_EQ(j.at("tasks").at(0).at("runs").get<std::uint64_t>(), 3U);
}

TEST(ExecutiveReport, LockstepReportsTheModelBesideTheMeasuredTime) {
  Rig rig;
  rig.add(spec("vision", 1, 0, 1ms), 2ms).model_by_activation([](std::size_t) { return 700us; });
  ExecutiveConfig cfg;
  cfg.judge_on_model = true;
  rig.build(cfg).run(3);
  const auto j = timing_json(*rig.exec);
  EXPECT_EQ(j.at("budgets_judged_on").get<std::string>(), "model");
  EXPECT_EQ(j.at("measured_on").get<std::string>(), "wall");
  const auto& t = j.at("tasks").at(0);
  EXPECT_EQ(t.at("overruns").get<std::uint64_t>(), 0U);
  EXPECT_EQ(t.at("measured_overruns").get<std::uint64_t>(), 3U);
  EXPECT_DOUBLE_EQ(t.at("model").at("max_us").get<double>(), 700.0);
  std::ostringstream table;
  print_timing_table(table, *rig.exec);
  EXPECT_NE(table.str().find("MODEL-P99"), std::string::npos) << table.str();
  EXPECT_NE(table.str().find("budgets judged on the modelled cost (lockstep)"), std::string::npos) << table.str();
}

TEST(ExecutiveReport, EventsAreDescribedWithNamesAndNumbers) {
  Scenario s;
  std::vector<std::string> lines;
  Event e;
  while (s.rig.events.pop(e)) lines.push_back(describe(e, s.exec()));
  ASSERT_FALSE(lines.empty());
  bool overrun = false;
  bool frame = false;
  bool failsafe = false;
  for (const auto& l : lines) {
    if (l.find("overrun: task 'planner'") != std::string::npos && l.find("frame 2") != std::string::npos) overrun = true;
    if (l.find("frame overrun: frame 5") != std::string::npos && l.find("2 frame(s) skipped") != std::string::npos) {
      frame = true;
    }
    if (l.find("FAILSAFE: task 'vision'") != std::string::npos) failsafe = true;
  }
  EXPECT_TRUE(overrun);
  EXPECT_TRUE(frame);
  EXPECT_TRUE(failsafe);
}

}  // namespace
}  // namespace ringlet::executive::test
