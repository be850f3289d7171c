// The cycle allocates nothing: the full simulated stack (sense with laser ray casting, the LLFSM
// schedule, actuate, telemetry, whiteboard dispatch, executive statistics) runs N frames while
// every operator new in the process is counted (tests/support/allocation_counter).
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "allocation_counter.hpp"
#include "ringlet/firmware/tasks/pddl_task.hpp"
#include "firmware_test_support.hpp"
#include "ringlet/firmware/stack.hpp"

namespace ringlet::firmware {
namespace {

using ringlet::test::AllocationCounter;

struct Allocations {
  std::uint64_t cycle = 0;  // in the cycle's thread
  std::uint64_t all = 0;    // in every thread (the workers' by design)
};

// Runs `frames` frames counting the allocations of the calling (cycle) thread and of all threads.
Allocations count_allocations(executive::Executive& exec, std::uint64_t frames) {
  ringlet::test::ThreadAllocationCounter thread;
  AllocationCounter counter;
  exec.run(frames);
  return {thread.count(), counter.count()};
}

TEST(NoAllocation, TheCounterSeesAnAllocation) {
  // Guards the test below against a counter that never counts.
  AllocationCounter counter;
  auto v = std::make_unique<std::vector<int>>(100, 1);
  EXPECT_GE(counter.count(), 2U);
  EXPECT_EQ(v->size(), 100U);
}

TEST(NoAllocation, FullSimulatedStackAllocatesNothingInTheCycle) {
  const auto cfg = test::parse_as_shipped(test::shipped_config_text());
  FirmwareStack stack(cfg);
  auto& exec = stack.executive();
  exec.run(1);  // start-up: the first frame may touch lazily initialised state
  constexpr std::uint64_t kFrames = 3000;  // 30 s of schedule time: driving, turning, goals reached
  std::uint64_t allocations = 0;
  {
    AllocationCounter counter;
    exec.run(kFrames);
    allocations = counter.count();
  }
  EXPECT_EQ(allocations, 0U) << "operator new was called inside the cycle";
  EXPECT_EQ(exec.frame_stats().frames, 1 + kFrames);
  EXPECT_GT(stack.telemetry().goals_reached(), 0U) << "the robot must actually drive during the counted frames";
}

// The hybrid controller: the planner (grid, regions, D* Lite, its repairs), the arbiter and the
// plan record, in P&B's test world where the dead end makes the planner replan.
TEST(NoAllocation, PlannerArbiterAndNavigateAllocateNothing) {
  const auto cfg = test::parse_as_shipped(test::shipped_config_text(test::kShippedConfig.parent_path() / "pb_test.toml"));
  FirmwareStack stack(cfg);
  auto& exec = stack.executive();
  exec.run(1);
  std::uint64_t allocations = 0;
  {
    AllocationCounter counter;
    exec.run(3000);  // 30 s: the first plan, into the dead end's mouth, the repairs around it
    allocations = counter.count();
  }
  EXPECT_EQ(allocations, 0U) << "operator new was called inside the cycle";
  ASSERT_NE(stack.telemetry().plans(), nullptr);
  EXPECT_GT(stack.telemetry().plans()->plans, 1U) << "the planner must have replanned in the counted frames";
  EXPECT_GT(stack.telemetry().plans()->cells.size(), 100U);
}

// The learned cost model learning online in P&B's training world: experiences recorded and added,
// rebuilds requested, new indexes' costs recomputed and switched, D* Lite repaired. The rebuild
// itself allocates, by design, on its worker thread: the cycle's thread is what is counted (and
// the counter's own per-thread count is checked to see that worker's allocations).
TEST(NoAllocation, TheLearnedModelLearningOnlineAllocatesNothingInTheCycle) {
  const auto text = test::with_line(test::shipped_config_text(test::kShippedConfig.parent_path() / "pb_training.toml"),
                                    "pops_per_slice", "pops_per_slice = 2000\ncost_model = \"knn\"\nlearn_online = true\npublish_every = 10");
  const auto cfg = test::parse_as_shipped(text);
  FirmwareStack stack(cfg);
  auto& exec = stack.executive();
  exec.run(1);
  // 30 s: about 40 experiences, a rebuild every second once they come
  const auto [cycle, all] = count_allocations(exec, 3000);
  EXPECT_EQ(cycle, 0U) << "operator new was called in the cycle's thread";
  EXPECT_GT(all, 0U) << "the rebuilds (on the worker thread) allocate: the counter must have seen them";
  EXPECT_GT(stack.experiences().experiences().size(), 10U);
}

TEST(NoAllocation, CameraAndVisionAllocateNothingEither) {
  // The main job's stack: the sim camera's render thread and the vision task run as well; the
  // counter sees every thread's allocations. Without [remote]: Cyclone DDS's own threads (and the
  // bridge, which serializes samples) allocate, off the cycle — the bridge reads the whiteboard by
  // generation, lock-free, on its own thread on the real clock, and after the frame (outside the
  // task table) in lockstep.
  const auto cfg = test::parse_as_shipped(
      test::with_line(test::shipped_config_text(test::kSplConfig), "enabled = true", "enabled = false"));
  ASSERT_FALSE(cfg.remote.enabled);
  FirmwareStack stack(cfg);
  auto& exec = stack.executive();
  exec.run(30);  // start-up: first frames rendered and processed
  std::uint64_t allocations = 0;
  {
    AllocationCounter counter;
    exec.run(300);  // 100 camera frames: kept short, it runs under qemu in the aarch64 stage
    allocations = counter.count();
  }
  EXPECT_EQ(allocations, 0U) << "operator new was called while the camera and vision ran";
  ASSERT_NE(stack.telemetry().vision(), nullptr);
  EXPECT_GT(stack.telemetry().vision()->frames, 95U);
  EXPECT_GT(stack.telemetry().vision()->lines, 0U);
}

}  // namespace
}  // namespace ringlet::firmware

namespace ringlet::firmware {
namespace {

// The PDDL planner service and the PlanExecute machine (issue 15) over the PDDL yard: the six
// operations, the sliced searches, NEXT_ACTION's believed state, the hand-over of the tasks the
// service thread grounds (LOAD_PDDL, then IS_OBSTACLE_KNOWN's new problem) and RE-PLAN. The
// service thread allocates, by design (parsing, grounding): the cycle's thread is what is counted.
TEST(NoAllocation, ThePddlServiceAndPlanExecuteAllocateNothingInTheCycle) {
  const auto cfg = ringlet::firmware::load_config(test::kShippedConfig.parent_path() / "pddl_yard.toml");
  FirmwareStack stack(cfg);
  auto& exec = stack.executive();
  exec.run(1);
  // 30 s: the load, the first plan, the crates, the new problem, the re-plan
  const auto [cycle, all] = count_allocations(exec, 3000);
  EXPECT_EQ(cycle, 0U) << "operator new was called in the cycle's thread";
  EXPECT_GT(all, 0U) << "the service thread parses and grounds: the counter must have seen it";
  const ringlet::firmware::PddlTask* pddl = nullptr;
  for (const auto& t : exec.tasks()) {
    if (const auto* p = dynamic_cast<const ringlet::firmware::PddlTask*>(t.task)) pddl = p;
  }
  ASSERT_NE(pddl, nullptr);
  EXPECT_EQ(pddl->counts().plans, 2U) << "the plan and the re-plan must fall in the counted frames";
  EXPECT_EQ(pddl->counts().obstacles_added, 1U);
}

}  // namespace
}  // namespace ringlet::firmware
