// The cyclic executive on virtual time, lockstep: the policies act on each task's modelled cost,
// not on the time the host measured.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "executive_test_support.hpp"
#include "ringlet/executive/executive.hpp"

namespace ringlet::executive::test {
namespace {

// Lockstep: the policy acts on the modelled cost, whatever the host measured; the measured
// overruns are counted beside it and change nothing.
TEST(ExecutiveModel, PoliciesActOnTheModelledCostNotOnTheMeasuredTime) {
  Rig rig;
  // Measured: every activation 6 ms against a 4 ms budget (a slow or loaded host).
  // Modelled: over budget in activations 2 and 5 only.
  rig.add(spec("vision", 1, 0, 4ms, OverrunPolicy::kSkip), 6ms).model_by_activation([](std::size_t n) {
    return n == 2 || n == 5 ? 5ms : 3ms;
  });
  ExecutiveConfig cfg;
  cfg.judge_on_model = true;
  auto& exec = rig.build(cfg);
  exec.run(10);
  const auto& s = exec.task_stats()[0];
  EXPECT_EQ(s.overruns, 2U) << "judged on the model";
  EXPECT_EQ(s.skipped, 2U) << "the skip policy acted on the modelled overruns only";
  EXPECT_EQ(s.runs, 8U);
  EXPECT_EQ(s.measured_overruns, 8U) << "every run was over budget on the measured clock";
  EXPECT_EQ(s.model.max(), 5ms);
  EXPECT_EQ(s.wall.max(), 6ms);
  // The overrun event carries the modelled cost.
  const auto overruns = of_kind(rig.drain(), EventKind::kOverrun);
  ASSERT_FALSE(overruns.empty());
  EXPECT_EQ(overruns.front().measured, 5ms);
}

TEST(ExecutiveModel, SameModelSameDecisionsWhateverTheMeasuredTimes) {
  // Two hosts: one fast, one slow and jittery. The degrade decisions are identical.
  std::vector<std::uint64_t> degraded;
  std::vector<std::vector<int>> levels(2);
  for (int host = 0; host < 2; ++host) {
    Rig rig;
    auto& t = rig.add(spec("vision", 1, 0, 4ms, OverrunPolicy::kDegrade), 1ms);
    t.cost_by_activation([host](std::size_t n) { return host == 0 ? 1ms : Nanos{(n * 7919 % 13) * 1'000'000}; });
    t.model_by_activation([](std::size_t n) { return n % 7 == 3 ? 6ms : 2ms; });
    t.on_run([&levels, host](const TaskContext& ctx) { levels[static_cast<std::size_t>(host)].push_back(ctx.degrade_level); });
    ExecutiveConfig cfg;
    cfg.judge_on_model = true;
    cfg.degrade_recover_after = 3;
    cfg.period = 20ms;
    auto& exec = rig.build(cfg);
    exec.run(60);
    degraded.push_back(exec.task_stats()[0].degraded_runs);
  }
  EXPECT_EQ(levels[0], levels[1]);
  EXPECT_EQ(degraded[0], degraded[1]);
  EXPECT_GT(degraded[0], 0U);
}

TEST(ExecutiveModel, WithoutTheModelTheMeasuredTimeIsJudgedAsBefore) {
  Rig rig;
  rig.add(spec("vision", 1, 0, 4ms, OverrunPolicy::kSkip), 6ms).model_by_activation([](std::size_t) { return 1ms; });
  auto& exec = rig.build();
  exec.run(10);
  EXPECT_EQ(exec.task_stats()[0].overruns, 5U);
  EXPECT_EQ(exec.task_stats()[0].measured_overruns, 5U);
}

}  // namespace
}  // namespace ringlet::executive::test
