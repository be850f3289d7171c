// The planners: every plan they return validates; the regression planner's plans are as short
// as a breadth-first search's (the oracle below, written plainly and unsliced); a sliced
// search returns exactly the unsliced plan; horizons, capacities and refusals are statuses.
#include <gtest/gtest.h>

#include <deque>
#include <map>
#include <vector>

#include "pddl_test_support.hpp"
#include "ringlet/pddl/lama_planner.hpp"
#include "ringlet/pddl/regression_planner.hpp"

namespace ringlet::pddl {
namespace {

using test::Grounded;
using test::ShippedProblem;

/// Breadth-first search forwards, whole states in a map: the length of a shortest plan, or -1.
int bfs_optimal_length(const Task& t) {
  using Bits = std::vector<std::uint64_t>;
  std::map<Bits, int> depth;
  std::deque<Bits> queue;
  const Bits start(t.initial.begin(), t.initial.end());
  depth[start] = 0;
  queue.push_back(start);
  Bits next(start.size());
  while (!queue.empty()) {
    const Bits s = queue.front();
    queue.pop_front();
    if (goal_holds(t, s)) return depth[s];
    for (std::int32_t op = 0; op < static_cast<std::int32_t>(t.operators.size()); ++op) {
      if (!applicable(t, op, s)) continue;
      apply(t, op, s, next);
      if (depth.emplace(next, depth[s] + 1).second) queue.push_back(next);
    }
  }
  return -1;
}

// Small enough for breadth-first search over subgoals.
const ShippedProblem kSmall[] = {{"gripper", "p01.pddl"},    {"gripper", "p02.pddl"},    {"blocksworld", "p01.pddl"},
                                 {"logistics", "p01.pddl"},  {"logistics", "p02.pddl"},  {"navigation", "p01.pddl"},
                                 {"navigation", "p02.pddl"}, {"navigation", "p03.pddl"}};

std::vector<std::int32_t> solve(Planner& p, const Task& t, std::uint32_t units, std::int32_t depth = kNoHorizon) {
  p.start(t, depth);
  EXPECT_EQ(test::run(p, units), PlannerStatus::kFound) << p.name() << ": " << p.reason();
  return {p.plan().begin(), p.plan().end()};
}

TEST(PddlRegression, PlansAreOptimalAgainstBreadthFirstSearchAndValidate) {
  for (const auto& sp : kSmall) {
    SCOPED_TRACE(sp.domain + "/" + sp.problem);
    const Grounded g = test::load_and_ground(sp);
    RegressionPlanner planner(PlannerLimits::for_task(g.task, 20000));
    const auto plan = solve(planner, g.task, 1000);
    const Validation v = test::check(g, plan);
    EXPECT_TRUE(v.valid) << v.reason;
    EXPECT_EQ(static_cast<int>(plan.size()), bfs_optimal_length(g.task));
    EXPECT_EQ(planner.stats().plan_cost, static_cast<std::int32_t>(plan.size()));
  }
}

TEST(PddlLama, EveryShippedProblemGetsAValidPlanWithItsCost) {
  for (const auto& sp : test::shipped_problems()) {
    SCOPED_TRACE(sp.domain + "/" + sp.problem);
    const Grounded g = test::load_and_ground(sp);
    LamaOptions first_and_one_restart;
    first_and_one_restart.restarts = 1;  // the large ones: w = 5 only, to keep the test short
    const bool large = sp.problem == "p03.pddl" || sp.problem == "p08.pddl";
    LamaPlanner planner(PlannerLimits::for_task(g.task, 60000), large ? first_and_one_restart : LamaOptions{});
    const auto plan = solve(planner, g.task, 5000);
    const Validation v = test::check(g, plan);
    EXPECT_TRUE(v.valid) << v.reason;
    EXPECT_EQ(planner.stats().plan_cost, static_cast<std::int32_t>(plan.size()));
    EXPECT_EQ(planner.stats().plan_length, static_cast<std::int32_t>(plan.size()));
    EXPECT_GE(planner.stats().plans_found, 1);
    EXPECT_GT(planner.stats().expansions, 0U);
  }
}

TEST(PddlLama, RestartsNeverMakeThePlanWorseAndReachTheOptimumOnSmallProblems) {
  for (const auto& sp : kSmall) {
    SCOPED_TRACE(sp.domain + "/" + sp.problem);
    const Grounded g = test::load_and_ground(sp);
    LamaOptions greedy_only;
    greedy_only.restarts = 0;
    LamaPlanner first(PlannerLimits::for_task(g.task, 20000), greedy_only);
    LamaPlanner anytime(PlannerLimits::for_task(g.task, 20000));
    const auto p1 = solve(first, g.task, 1000);
    const auto p2 = solve(anytime, g.task, 1000);
    EXPECT_LE(p2.size(), p1.size());
    EXPECT_TRUE(test::check(g, p2).valid);
    // The last restart is A* with h_FF, not admissible: the optimum is not promised, but these
    // small problems reach it.
    EXPECT_EQ(static_cast<int>(p2.size()), bfs_optimal_length(g.task));
  }
}

TEST(PddlLama, ConditionalEffectsArePlannedThrough) {
  const Grounded g = test::load_and_ground({"briefcase", "p02.pddl"});
  LamaPlanner planner(PlannerLimits::for_task(g.task, 10000));
  const auto plan = solve(planner, g.task, 100);
  EXPECT_TRUE(test::check(g, plan).valid);
  EXPECT_EQ(static_cast<int>(plan.size()), bfs_optimal_length(g.task));
  RegressionPlanner regression(PlannerLimits::for_task(g.task, 10000));
  EXPECT_EQ(regression.start(g.task, kNoHorizon), PlannerStatus::kFailed);
  EXPECT_STREQ(regression.reason(), "the regression planner does not handle conditional effects: use the lama planner");
}

TEST(PddlPlanners, ASlicedSearchReturnsTheUnslicedPlan) {
  for (const auto& sp : {ShippedProblem{"gripper", "p02.pddl"}, ShippedProblem{"blocksworld", "p01.pddl"},
                         ShippedProblem{"logistics", "p02.pddl"}, ShippedProblem{"navigation", "p03.pddl"}}) {
    SCOPED_TRACE(sp.domain + "/" + sp.problem);
    const Grounded g = test::load_and_ground(sp);
    const auto limits = PlannerLimits::for_task(g.task, 20000);
    RegressionPlanner r(limits);
    LamaPlanner l(limits);
    const auto r_whole = solve(r, g.task, 1U << 30U);
    const auto r_stats = r.stats();
    const auto l_whole = solve(l, g.task, 1U << 30U);
    const auto l_stats = l.stats();
    EXPECT_EQ(r_stats.slices, 1U);
    for (const std::uint32_t units : {1U, 7U, 100U}) {
      EXPECT_EQ(solve(r, g.task, units), r_whole) << units;
      EXPECT_EQ(r.stats().expansions, r_stats.expansions);
      EXPECT_LE(r.stats().max_units_in_slice, units);
      EXPECT_EQ(solve(l, g.task, units), l_whole) << units;
      EXPECT_EQ(l.stats().expansions, l_stats.expansions);
      EXPECT_EQ(l.stats().plans_found, l_stats.plans_found);
      EXPECT_LE(l.stats().max_units_in_slice, units);
      EXPECT_GT(l.stats().slices, units == 100U ? 1U : 10U);
    }
  }
}

TEST(PddlPlanners, TheDepthIsAHorizon) {
  const Grounded g = test::load_and_ground({"navigation", "p02.pddl"});  // optimum: 8 actions
  const auto limits = PlannerLimits::for_task(g.task, 20000);
  RegressionPlanner r(limits);
  LamaPlanner l(limits);
  for (Planner* p : {static_cast<Planner*>(&r), static_cast<Planner*>(&l)}) {
    SCOPED_TRACE(p->name());
    p->start(g.task, 7);
    EXPECT_EQ(test::run(*p, 50), PlannerStatus::kExhausted);
    EXPECT_STREQ(p->reason(), "no plan within the horizon of 7 actions");
    EXPECT_TRUE(p->plan().empty());
    const auto plan = solve(*p, g.task, 50, 8);
    EXPECT_EQ(plan.size(), 8U);
    EXPECT_TRUE(test::check(g, plan).valid);
  }
}

TEST(PddlPlanners, RunningOutOfNodesIsAFailureWithAReason) {
  const Grounded g = test::load_and_ground({"blocksworld", "p02.pddl"});
  const auto limits = PlannerLimits::for_task(g.task, 50);
  RegressionPlanner r(limits);
  r.start(g.task, kNoHorizon);
  EXPECT_EQ(test::run(r, 10), PlannerStatus::kFailed);
  EXPECT_STREQ(r.reason(), "node capacity (50 subgoals) exhausted before a plan was found");
  // Greedy search finds a plan inside 50 states here; a restart then runs out: the plan found
  // is kept (anytime) and the reason says why it was not improved further.
  const Grounded hard = test::load_and_ground({"blocksworld", "p03.pddl"});
  LamaPlanner anytime(PlannerLimits::for_task(hard.task, 50));
  anytime.start(hard.task, kNoHorizon);
  EXPECT_EQ(test::run(anytime, 10), PlannerStatus::kFound);
  EXPECT_STREQ(anytime.reason(), "stopped improving: node capacity (50) reached in restart 0");
  EXPECT_TRUE(test::check(hard, anytime.plan()).valid);
  LamaPlanner l(PlannerLimits::for_task(hard.task, 5));
  l.start(hard.task, kNoHorizon);
  EXPECT_EQ(test::run(l, 10), PlannerStatus::kFailed);
  EXPECT_STREQ(l.reason(), "node capacity (5 states) exhausted before a plan was found");
  // A task larger than the limits is refused at start.
  PlannerLimits small = limits;
  small.max_facts = 3;
  LamaPlanner s(small);
  EXPECT_EQ(s.start(g.task, kNoHorizon), PlannerStatus::kFailed);
  EXPECT_NE(std::string(s.reason()).find("exceeds the planner's limits"), std::string::npos);
}

TEST(PddlPlanners, AnUnsolvableProblemExhaustsTheSpace) {
  // Every way into p33 blocked: no plan at all.
  const Grounded g = test::load_and_ground({"navigation", "p01.pddl"});
  const std::string dir = test::domains_dir() + "/navigation/";
  const std::string walled = R"((define (problem walled) (:domain navigation)
    (:objects robot1 - robot a b c - place)
    (:init (at robot1 a) (connected a b) (connected b a) (connected b c) (blocked b c))
    (:goal (at robot1 c))))";
  auto p = parse_problem(walled, "walled.pddl", g.files.domain);
  ASSERT_TRUE(std::holds_alternative<Problem>(p));
  Arena arena(1 << 16);
  const GroundResult gr = ground(g.files.domain, std::get<Problem>(p), arena);
  ASSERT_EQ(gr.status, GroundStatus::kOk);
  const auto limits = PlannerLimits::for_task(gr.task, 1000);
  RegressionPlanner r(limits);
  LamaPlanner l(limits);
  for (Planner* planner : {static_cast<Planner*>(&r), static_cast<Planner*>(&l)}) {
    planner->start(gr.task, kNoHorizon);
    EXPECT_EQ(test::run(*planner, 5), PlannerStatus::kExhausted) << planner->name();
  }
}

TEST(PddlPlanners, ReplanningFromAnotherSourceState) {
  // RE-PLAN(source): the robot stands at p32 now.
  const Grounded g = test::load_and_ground({"navigation", "p01.pddl"});
  std::vector<std::uint64_t> source(static_cast<std::size_t>(g.task.words));
  std::int32_t at_p32 = -1;
  for (std::int32_t f = 0; f < g.task.fact_count; ++f) {
    if (fact_text(g.task, f) == "(at robot1 p32)") at_p32 = f;
  }
  ASSERT_GE(at_p32, 0);
  set(source, at_p32);
  const auto limits = PlannerLimits::for_task(g.task, 1000);
  RegressionPlanner r(limits);
  LamaPlanner l(limits);
  for (Planner* p : {static_cast<Planner*>(&r), static_cast<Planner*>(&l)}) {
    p->start(g.task, kNoHorizon, source);
    ASSERT_EQ(test::run(*p, 3), PlannerStatus::kFound) << p->reason();
    ASSERT_EQ(p->plan().size(), 1U);
    EXPECT_EQ(operator_text(g.task, p->plan()[0]), "(drive robot1 p32 p33)");
  }
}

}  // namespace
}  // namespace ringlet::pddl
