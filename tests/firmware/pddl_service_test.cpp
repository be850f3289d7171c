// The PDDL planner service (issue 15, item 3): the six operations over the whiteboard, their
// error replies, idempotency by id, and the plan-execute-replan scenario (item 5) in lockstep,
// also over a seeded lossy link that drops, repeats and reorders requests and replies.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "firmware_test_support.hpp"
#include "ringlet/firmware/config.hpp"
#include "ringlet/firmware/mission_report.hpp"
#include "ringlet/firmware/mission_runner.hpp"
#include "ringlet/firmware/stack.hpp"
#include "ringlet/firmware/tasks/pddl_task.hpp"

namespace ringlet::firmware {
namespace {

const std::filesystem::path kYardConfig = test::kShippedConfig.parent_path() / "pddl_yard.toml";

// The task alone on a whiteboard, as the machine would talk to it (a perfect link).
struct Service {
  explicit Service(PddlSettings s = load_config(kYardConfig).pddl) : settings(std::move(s)) {
    task = std::make_unique<PddlTask>(settings, board, false);
  }
  // Posts the request with a new id and runs the task until the reply with that id (or 500 activations).
  wb::PddlReply ask(wb::PddlOp op, std::string_view text = {}, std::int32_t depth = 0, std::int32_t rank = 0,
                    double x = 0.0, double y = 0.0) {
    wb::PddlRequest r{};
    r.id = ++id;
    r.op = op;
    r.text = text;
    r.depth = depth;
    r.rank = rank;
    r.x = x;
    r.y = y;
    return send(r);
  }
  wb::PddlReply send(const wb::PddlRequest& r) {
    for (int i = 0; i < 500; ++i) {
      board.post(r);  // the machine's write-back: every ringlet until answered
      task->run(executive::TaskContext{});
      const auto reply = board.get<wb::PddlReply>();
      if (reply.id == r.id && board.generation<wb::PddlReply>() > 0) return reply;
    }
    ADD_FAILURE() << "no reply to request " << r.id;
    return {};
  }
  PddlSettings settings;
  wb::Whiteboard board{64};
  std::unique_ptr<PddlTask> task;
  std::uint32_t id = 0;
};

std::string reason(const wb::PddlReply& r) { return std::string(r.reason.view()); }

TEST(PddlService, EveryOperationBeforeItsPrerequisiteIsRefusedWithTheReason) {
  Service s;
  auto r = s.ask(wb::PddlOp::kStartPlanner);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(reason(r), "no problem loaded (LOAD_PDDL first)");
  r = s.ask(wb::PddlOp::kNextAction, {}, 0, 0);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(reason(r), "no plan (START_PLANNER or RE-PLAN first)");
  r = s.ask(wb::PddlOp::kIsObstacleKnown, {}, 0, 0, 14.2, 3.0);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(reason(r), "no problem loaded (LOAD_PDDL first)");
  r = s.ask(wb::PddlOp::kLoadPlanner, "ff");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(reason(r), "unknown planner \"ff\": regression or lama");
  r = s.ask(wb::PddlOp::kLoadPddl, "yard.pddl");
  ASSERT_TRUE(r.ok) << reason(r);
  EXPECT_EQ(reason(r), "pddl-yard: 12 facts, 30 operators");
  r = s.ask(wb::PddlOp::kStartPlanner);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(reason(r), "no planner chosen (LOAD_PLANNER first)");
  r = s.ask(wb::PddlOp::kReplan, "at robot1 p21");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(reason(r), "no planner chosen (LOAD_PLANNER first)");
}

TEST(PddlService, BadProblemFilesAreRefusedWithTheirLocation) {
  const auto dir = std::filesystem::temp_directory_path() / ("ringlet_pddl_service_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "broken.pddl") << "(define (problem b) (:domain navigation)\n  (:objects r - robot a - place)\n"
                                        "  (:init (at r a) (at r))\n  (:goal (at r a)))\n";
  PddlSettings settings = load_config(kYardConfig).pddl;
  settings.problems = dir;
  Service s(settings);
  auto r = s.ask(wb::PddlOp::kLoadPddl, "broken.pddl");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(reason(r), (dir / "broken.pddl").string() + ":3:20: predicate at takes 2 argument(s), given 1");
  r = s.ask(wb::PddlOp::kLoadPddl, "missing.pddl");
  EXPECT_FALSE(r.ok);
  EXPECT_NE(reason(r).find("missing.pddl"), std::string::npos) << reason(r);
  r = s.ask(wb::PddlOp::kLoadPddl, "../broken.pddl");
  EXPECT_FALSE(r.ok);
  EXPECT_NE(reason(r).find("LOAD_PDDL takes the name of a file in"), std::string::npos) << reason(r);
  std::filesystem::remove_all(dir);
}

TEST(PddlService, PlansGivesActionsByRankAndReplansAroundANewObstacle) {
  Service s;
  ASSERT_TRUE(s.ask(wb::PddlOp::kLoadPlanner, "regression").ok);
  ASSERT_TRUE(s.ask(wb::PddlOp::kLoadPddl, "yard.pddl").ok);
  auto r = s.ask(wb::PddlOp::kStartPlanner);
  ASSERT_TRUE(r.ok) << reason(r);
  EXPECT_EQ(r.plan, 1U);
  EXPECT_EQ(r.plan_length, 3);  // p11 p21 p31 p41
  r = s.ask(wb::PddlOp::kNextAction, {}, 0, 1);
  ASSERT_TRUE(r.ok) << reason(r);
  EXPECT_EQ(r.rank, 1);
  EXPECT_EQ(r.action, "drive");
  EXPECT_EQ(r.args, "robot1 p21 p31");
  EXPECT_EQ(r.arg_count, 3);
  EXPECT_EQ(r.arg_place[0], 0);
  EXPECT_EQ(r.arg_place[2], 1);
  EXPECT_DOUBLE_EQ(r.arg_x[2], 12.0);
  EXPECT_DOUBLE_EQ(r.arg_y[2], 3.0);
  r = s.ask(wb::PddlOp::kNextAction, {}, 0, 3);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(reason(r), "rank 3 is past the end of plan 1 (3 actions)");
  r = s.ask(wb::PddlOp::kNextAction, {}, 0, 2);  // actions 0 and 1 are done: the robot is at p31
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.args, "robot1 p31 p41");
  // The crates between p31 and p41: not in the problem, so added (both directions); then known.
  r = s.ask(wb::PddlOp::kIsObstacleKnown, {}, 0, 0, 14.2, 3.1);
  ASSERT_TRUE(r.ok) << reason(r);
  EXPECT_FALSE(r.known);
  EXPECT_EQ(reason(r), "(blocked p31 p41) (blocked p41 p31) added");
  r = s.ask(wb::PddlOp::kIsObstacleKnown, {}, 0, 0, 14.3, 2.9);
  ASSERT_TRUE(r.ok);
  EXPECT_TRUE(r.known);
  EXPECT_EQ(reason(r), "known: (blocked p31 p41) at (14.30, 2.90)");
  r = s.ask(wb::PddlOp::kIsObstacleKnown, {}, 0, 0, 7.3, 5.0);  // the known wall between p21 and p22
  ASSERT_TRUE(r.ok);
  EXPECT_TRUE(r.known) << reason(r);
  r = s.ask(wb::PddlOp::kIsObstacleKnown, {}, 0, 0, 0.5, 13.5);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(reason(r), "no connection between places passes within 0.80 m of (0.50, 13.50)");
  // The new problem's initial state is the believed one: the robot at p31.
  EXPECT_EQ(s.ask(wb::PddlOp::kNextAction, {}, 0, 0).ok, false);  // the old plan is gone with its task
  r = s.ask(wb::PddlOp::kReplan, "(at robot1 p31)");
  ASSERT_TRUE(r.ok) << reason(r);
  EXPECT_EQ(r.plan, 2U);
  EXPECT_EQ(r.plan_length, 5);  // p32 p33 p43 p42 p41: (p32 p42) is a known wall
  r = s.ask(wb::PddlOp::kNextAction, {}, 0, 0);
  EXPECT_EQ(r.args, "robot1 p31 p32");
  EXPECT_EQ(r.plan, 2U);
  r = s.ask(wb::PddlOp::kReplan, "at robot1 p99");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(reason(r), "source (at robot1 p99) is not a fact of the task: an unknown predicate or object, or never reachable");
  r = s.ask(wb::PddlOp::kReplan, "at robot1 p31", 4);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(reason(r), "no plan of at most 4 actions from the source");
  r = s.ask(wb::PddlOp::kLoadPlanner, "LAMA");
  ASSERT_TRUE(r.ok);
  r = s.ask(wb::PddlOp::kReplan, "at robot1 p31");
  ASSERT_TRUE(r.ok) << reason(r);
  EXPECT_EQ(r.plan_length, 5);
}

TEST(PddlService, RequestsAreCarriedOutOncePerIdAndStaleOnesIgnored) {
  Service s;
  ASSERT_TRUE(s.ask(wb::PddlOp::kLoadPlanner, "lama").ok);
  ASSERT_TRUE(s.ask(wb::PddlOp::kLoadPddl, "yard.pddl").ok);
  wb::PddlRequest start{};
  start.id = ++s.id;
  start.op = wb::PddlOp::kStartPlanner;
  const auto first = s.send(start);
  ASSERT_TRUE(first.ok);
  const auto carried = s.task->counts().carried_out;
  const auto plans = s.task->counts().plans;
  // The same id again (the reply was lost): the same reply, the planner not started again.
  const auto again = s.send(start);
  EXPECT_EQ(again.plan, first.plan);
  EXPECT_EQ(reason(again), reason(first));
  EXPECT_EQ(s.task->counts().carried_out, carried);
  EXPECT_EQ(s.task->counts().plans, plans);
  EXPECT_GE(s.task->counts().repeated, 1U);
  // A newer request, then an older one arriving late: ignored, no reply to it.
  ASSERT_TRUE(s.ask(wb::PddlOp::kNextAction, {}, 0, 0).ok);
  wb::PddlRequest late = start;
  late.id = s.id - 1;
  s.board.post(late);
  const auto replies = s.board.generation<wb::PddlReply>();
  s.task->run(executive::TaskContext{});
  EXPECT_EQ(s.board.generation<wb::PddlReply>(), replies);
  EXPECT_EQ(s.task->counts().stale, 1U);
  EXPECT_EQ(s.task->counts().plans, plans);
}

struct ScenarioRun {
  MissionSummary summary;
  std::uint64_t overruns = 0;
  executive::TaskStats pddl{};
  PddlServiceCounts counts{};
  LossyLinkCounts requests{}, replies{};
  std::vector<std::vector<hal::WorldPoint>> plans;  // as pddl_record drew them
  std::vector<hal::WorldPoint> reported;
};

// The plans pddl_record drew, one polyline per plan number, and the reported obstacles.
void copy_picture(const hal::PlanPicture& p, ScenarioRun& r) {
  std::size_t begin = 0;
  for (const std::uint32_t end : p.plan_ends) {
    r.plans.emplace_back(p.plan_points.begin() + static_cast<std::ptrdiff_t>(begin),
                         p.plan_points.begin() + static_cast<std::ptrdiff_t>(end));
    begin = end;
  }
  r.reported.assign(p.reported.begin(), p.reported.end());
}

// The places of yard.pddl ([pddl] places in pddl_yard.toml): column c, row r.
hal::WorldPoint place(int c, int row) { return {3.0 + 4.5 * (c - 1), 3.0 + 4.0 * (row - 1)}; }

void expect_the_yards_two_plans(const ScenarioRun& r) {
  const std::vector<hal::WorldPoint> first{place(1, 1), place(2, 1), place(3, 1), place(4, 1)};
  const std::vector<hal::WorldPoint> second{place(3, 1), place(3, 2), place(3, 3), place(4, 3), place(4, 2), place(4, 1)};
  ASSERT_EQ(r.plans.size(), 2U) << "the first plan and the re-plan from p31, each drawn once";
  const auto same = [](const std::vector<hal::WorldPoint>& a, const std::vector<hal::WorldPoint>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (a[i].x != b[i].x || a[i].y != b[i].y) return false;
    return true;
  };
  EXPECT_TRUE(same(r.plans[0], first)) << "straight along the bottom row to p41";
  EXPECT_TRUE(same(r.plans[1], second)) << "round the crates and the known wall";
  ASSERT_EQ(r.reported.size(), 1U) << "one IS_OBSTACLE_KNOWN, however often it was sent";
  EXPECT_GT(r.reported[0].x, place(3, 1).x);
  EXPECT_LT(r.reported[0].x, place(4, 1).x);
  EXPECT_NEAR(r.reported[0].y, place(3, 1).y, 1.0) << "on the leg p31 -> p41";
}

ScenarioRun run_yard(const std::string& extra = {}) {
  std::string text = test::shipped_config_text(kYardConfig);
  if (!extra.empty()) text = test::with_line(text, "units_per_slice", extra);
  const auto cfg = parse_config(text, kYardConfig.string(), kYardConfig.parent_path());
  FirmwareStack stack(cfg);
  std::atomic<bool> interrupt{false};
  std::ostringstream log;
  const auto outcome = run_mission(stack, cfg.mission.timeout_s, interrupt, log);
  ScenarioRun r;
  r.summary = summarize(stack, outcome, stack.executive().failsafe_triggered() || outcome.watchdog_fired);
  const auto& tasks = stack.executive().tasks();
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    r.overruns += stack.executive().task_stats()[i].overruns;
    if (const auto* p = dynamic_cast<const PddlTask*>(tasks[i].task)) {
      r.pddl = stack.executive().task_stats()[i];
      r.counts = p->counts();
      r.requests = p->requests_link();
      r.replies = p->replies_link();
    }
  }
  copy_picture(stack.telemetry().plan_picture(), r);
  return r;
}

TEST(PddlScenario, TheYardCompletesInLockstepAfterReplanningAroundTheCrates) {
  const ScenarioRun r = run_yard();
  EXPECT_TRUE(r.summary.complete);
  EXPECT_EQ(r.summary.collisions, 0U);
  EXPECT_EQ(r.overruns, 0U);
  EXPECT_FALSE(r.summary.safe_state);
  EXPECT_EQ(r.counts.obstacles_added, 1U) << "the crates are the one obstacle the problem did not know";
  EXPECT_EQ(r.counts.plans, 2U) << "START_PLANNER, then RE-PLAN from p31";
  EXPECT_EQ(r.counts.stale, 0U);
  EXPECT_LT(r.summary.mission_seconds, 60.0);
  expect_the_yards_two_plans(r);
  std::printf("pddl_yard: %.2f s, %.1f m, trajectory %016llx run %016llx, pddl model max %lld ns, units max %u\n",
              r.summary.mission_seconds, r.summary.distance_m, static_cast<unsigned long long>(r.summary.trajectory_hash),
              static_cast<unsigned long long>(r.summary.run_hash), static_cast<long long>(r.pddl.model.max().count()),
              r.counts.max_units);
}

TEST(PddlScenario, TwoLockstepRunsAreBitIdentical) {
  const ScenarioRun a = run_yard();
  const ScenarioRun b = run_yard();
  EXPECT_EQ(a.summary.trajectory_hash, b.summary.trajectory_hash);
  EXPECT_EQ(a.summary.run_hash, b.summary.run_hash);
}

// Mi-Pal's reason for numbering the actions: a whiteboard distributed over UDP. A seeded link
// loses 30 % of the requests and replies, repeats 30 % and delays each by up to 8 activations
// (so they also arrive out of order); the machine and the service still finish the mission.
TEST(PddlScenario, ALossyLinkThatDropsRepeatsAndReordersStillCompletesTheMission) {
  const ScenarioRun r = run_yard("units_per_slice = 200\nlink_drop = 0.3\nlink_duplicate = 0.3\nlink_max_delay = 8\nlink_seed = 7");
  EXPECT_TRUE(r.summary.complete);
  EXPECT_EQ(r.summary.collisions, 0U);
  EXPECT_EQ(r.overruns, 0U);
  EXPECT_EQ(r.counts.obstacles_added, 1U);
  EXPECT_EQ(r.counts.plans, 2U) << "a repeated START_PLANNER or RE-PLAN must not plan again";
  EXPECT_GT(r.requests.dropped, 0U);
  EXPECT_GT(r.replies.dropped, 0U);
  EXPECT_GT(r.requests.duplicated + r.replies.duplicated, 0U);
  EXPECT_GT(r.counts.repeated, 0U) << "lost replies are answered again from the id";
  EXPECT_GT(r.counts.stale, 0U) << "late copies of older requests arrive and are ignored";
  expect_the_yards_two_plans(r);
  std::printf("lossy: requests %llu pushed %llu dropped %llu duplicated; replies %llu pushed %llu dropped; "
              "repeated %llu stale %llu; %.2f s\n",
              static_cast<unsigned long long>(r.requests.pushed), static_cast<unsigned long long>(r.requests.dropped),
              static_cast<unsigned long long>(r.requests.duplicated), static_cast<unsigned long long>(r.replies.pushed),
              static_cast<unsigned long long>(r.replies.dropped), static_cast<unsigned long long>(r.counts.repeated),
              static_cast<unsigned long long>(r.counts.stale), r.summary.mission_seconds);
}

}  // namespace
}  // namespace ringlet::firmware
