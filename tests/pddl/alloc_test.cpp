// After construction, start() and every step() of both planners allocate nothing, through
// greedy search, every weighted A* restart and a horizon (the allocation counter replaces the
// global operator new, so this is its own executable).
#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "pddl_test_support.hpp"
#include "ringlet/pddl/lama_planner.hpp"
#include "ringlet/pddl/regression_planner.hpp"

namespace ringlet::pddl {
namespace {

TEST(PddlNoAllocation, StartAndStepAllocateNothing) {
  for (const auto& sp : {test::ShippedProblem{"gripper", "p04.pddl"}, test::ShippedProblem{"briefcase", "p02.pddl"},
                         test::ShippedProblem{"navigation", "p03.pddl"}}) {
    SCOPED_TRACE(sp.domain);
    const auto g = test::load_and_ground(sp);
    const auto limits = PlannerLimits::for_task(g.task, 100000);
    LamaPlanner lama(limits);
    RegressionPlanner regression(limits);
    std::uint64_t steps = 0;
    const std::uint64_t before = ringlet::test::allocations();
    for (const std::int32_t depth : {kNoHorizon, 3}) {
      for (Planner* p : {static_cast<Planner*>(&lama), static_cast<Planner*>(&regression)}) {
        PlannerStatus s = p->start(g.task, depth);
        for (; s == PlannerStatus::kRunning; ++steps) s = p->step(7);
      }
    }
    EXPECT_EQ(ringlet::test::allocations() - before, 0U);
    EXPECT_GT(steps, 10U);
    EXPECT_GE(lama.stats().plans_found, 0);
  }
}

}  // namespace
}  // namespace ringlet::pddl
