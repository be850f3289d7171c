// The validator: a correct plan passes; hand-written wrong ones are refused naming the step and
// the precondition, the goal literal, or the unknown object; plan files with errors are located.
#include <gtest/gtest.h>

#include <string>

#include "pddl_test_support.hpp"
#include "ringlet/pddl/plan_file.hpp"

namespace ringlet::pddl {
namespace {

Validation check_text(const test::Grounded& g, const std::string& plan) {
  auto steps = parse_plan(plan, "plan.txt");
  EXPECT_TRUE(std::holds_alternative<std::vector<PlanStep>>(steps)) << std::get<Error>(steps).to_string();
  return validate(g.files.domain, g.files.problem, std::get<std::vector<PlanStep>>(steps));
}

TEST(PddlValidator, AGoodPlanPasses) {
  const auto g = test::load_and_ground({"gripper", "p01.pddl"});
  const Validation v = check_text(g, "; carry one ball\n(pick ball1 rooma left)\n(move rooma roomb)\n(drop ball1 roomb left)\n");
  EXPECT_TRUE(v.valid) << v.reason;
}

TEST(PddlValidator, AMissingPreconditionNamesStepAndFact) {
  const auto g = test::load_and_ground({"gripper", "p01.pddl"});
  const Validation v = check_text(g, "(pick ball1 rooma left)\n(drop ball1 roomb left)\n");
  EXPECT_FALSE(v.valid);
  EXPECT_EQ(v.step, 2);
  EXPECT_EQ(v.reason, "plan.txt:2:2: step 2 (drop ball1 roomb left): precondition (at-robby roomb) does not hold");
}

TEST(PddlValidator, AWrongGoalNamesTheGoalLiteral) {
  const auto g = test::load_and_ground({"gripper", "p01.pddl"});
  const Validation v = check_text(g, "(pick ball1 rooma left)\n(move rooma roomb)\n");
  EXPECT_FALSE(v.valid);
  EXPECT_EQ(v.step, 0);
  EXPECT_EQ(v.reason, "the goal (at ball1 roomb) does not hold after the plan's 2 step(s)");
}

TEST(PddlValidator, AnUnknownObjectIsNamed) {
  const auto g = test::load_and_ground({"gripper", "p01.pddl"});
  const Validation v = check_text(g, "(pick ball1 rooma left)\n(move rooma kitchen)\n");
  EXPECT_FALSE(v.valid);
  EXPECT_EQ(v.reason, "plan.txt:2:2: step 2 (move rooma kitchen): unknown object kitchen");
}

TEST(PddlValidator, UnknownActionsArityAndTypesAreRefused) {
  const auto g = test::load_and_ground({"gripper", "p01.pddl"});
  EXPECT_EQ(check_text(g, "(fly rooma roomb)").reason, "plan.txt:1:2: step 1 (fly rooma roomb): unknown action fly");
  EXPECT_EQ(check_text(g, "(move rooma)").reason,
            "plan.txt:1:2: step 1 (move rooma): move takes 2 parameter(s), given 1");
  EXPECT_EQ(check_text(g, "(move rooma ball1)").reason,
            "plan.txt:1:2: step 1 (move rooma ball1): ball1 is of type ball, parameter ?to is of type room");
}

TEST(PddlValidator, NegativePreconditionsAndEqualityAreChecked) {
  const auto g = test::load_and_ground({"navigation", "p01.pddl"});
  // The passage p21 -> p22 is blocked; driving to where the robot is violates (not (= ..)).
  EXPECT_EQ(check_text(g, "(drive robot1 p11 p21)\n(drive robot1 p21 p22)").reason,
            "plan.txt:2:2: step 2 (drive robot1 p21 p22): precondition (not (blocked p21 p22)) does not hold");
  EXPECT_EQ(check_text(g, "(drive robot1 p11 p11)").reason,
            "plan.txt:1:2: step 1 (drive robot1 p11 p11): precondition (connected p11 p11) does not hold");
}

TEST(PddlValidator, ConditionalEffectsMoveTheContents) {
  const auto g = test::load_and_ground({"briefcase", "p01.pddl"});
  EXPECT_TRUE(check_text(g, "(put-in book home) (move home office) (take-out book) (move office home)").valid);
  // Without put-in the book stays home.
  EXPECT_EQ(check_text(g, "(move home office) (move office home)").reason,
            "the goal (at book office) does not hold after the plan's 2 step(s)");
}

TEST(PddlValidator, PlanFileErrorsAreLocated) {
  auto bad = parse_plan("(pick a b)\n  pick c)", "plan.txt");
  ASSERT_TRUE(std::holds_alternative<Error>(bad));
  EXPECT_EQ(std::get<Error>(bad).to_string(), "plan.txt:2:3: expected \"(\" to start a plan step, found \"pick\"");
  auto unclosed = parse_plan("(pick a b", "plan.txt");
  ASSERT_TRUE(std::holds_alternative<Error>(unclosed));
  EXPECT_EQ(std::get<Error>(unclosed).to_string(), "plan.txt:1:10: expected an object or \")\", found end of file");
}

}  // namespace
}  // namespace ringlet::pddl
