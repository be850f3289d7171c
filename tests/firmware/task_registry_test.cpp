// A task from outside the firmware joins the stack through the production registry: its file
// (fixture_tasks.hpp), one registry line and one table row. Its contract is checked at start-up
// like every production task's.
#include <gtest/gtest.h>

#include <regex>

#include "firmware_test_support.hpp"
#include "fixture_tasks.hpp"
#include "ringlet/firmware/stack.hpp"
#include "ringlet/firmware/task_registry.hpp"

namespace ringlet::firmware {
namespace {

using test::parse_as_shipped;
using test::shipped_config_text;
using test::with_line;

// The courtyard with one more row in its table, after telemetry.
FirmwareConfig with_row(const std::string& row) {
  return parse_as_shipped(with_line(shipped_config_text(), "  { name = \"telemetry\"",
                                    row + "\n  { name = \"telemetry\", budget_us = 100, policy = \"skip\" },"));
}

TEST(TaskRegistry, ProductionTasksAreRegisteredOnceEach) {
  const TaskRegistry registry = production_tasks();
  for (const char* name : {"sense", "ball_sensor", "goals", "vision", "planner", "arbiter", "fsm", "actuate", "telemetry",
                           "plan_record", "whiteboard", "pddl", "pddl_record", "sense_no_gps", "localization"}) {
    const RegisteredTask* t = registry.find(name);
    ASSERT_NE(t, nullptr) << name;
    EXPECT_EQ(t->declaration->name, name);
    EXPECT_NE(t->declaration->location().find("_task.hpp:"), std::string::npos) << "declared in its own file";
  }
  EXPECT_EQ(registry.tasks().size(), 15U);
  EXPECT_EQ(registry.find("no_such_task"), nullptr);
}

TEST(TaskRegistry, AFixtureTaskRunsInTheStack) {
  TaskRegistry registry = production_tasks();
  registry.add<test::PrintPoseTask>();
  FirmwareStack stack(with_row("  { name = \"print_pose\", every = 10, budget_us = 50 },"), registry);
  stack.executive().run(100);
  EXPECT_EQ(stack.whiteboard().generation<wb::Print>(), 10U) << "once every 10 frames";
  const std::string text(stack.whiteboard().get<wb::Print>().text.view());
  EXPECT_EQ(text.rfind("at ", 0), 0U) << text;
  EXPECT_NE(text, "at 0.00 0.00") << "it read the pose sense posted";
}

TEST(TaskRegistry, ARequiredTypeNobodyProvidesFailsStartUpWithTheTasksFileAndLine) {
  TaskRegistry registry = production_tasks();
  registry.add<test::NeedsLinesTask>();
  try {
    FirmwareStack stack(with_row("  { name = \"needs_lines\", budget_us = 50 },"), registry);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    const std::string m = e.what();
    EXPECT_TRUE(std::regex_search(
        m, std::regex(R"(\n  - [^\n]*tests/firmware/fixture_tasks\.hpp:\d+: task 'needs_lines' requires 'FieldLines', )"
                      R"(but no task in the table \([^)]*courtyard\.toml:\d+:\d+\) or machine provides it)")))
        << m;
  }
}

TEST(TaskRegistry, ARegisteredTaskThatIsNotInTheTableDoesNotRun) {
  TaskRegistry registry = production_tasks();
  registry.add<test::PrintPoseTask>();
  FirmwareStack stack(parse_as_shipped(shipped_config_text()), registry);
  stack.executive().run(20);
  EXPECT_EQ(stack.whiteboard().generation<wb::Print>(), 0U);
}

}  // namespace
}  // namespace ringlet::firmware
