// Grounding: relaxed reachability instantiates only what can happen, static facts disappear,
// lists are sorted sets, and an arena too small is a status that names what did not fit.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "pddl_test_support.hpp"
#include "ringlet/pddl/parser.hpp"

namespace ringlet::pddl {
namespace {

std::set<std::string> fact_names(const Task& t) {
  std::set<std::string> s;
  for (std::int32_t f = 0; f < t.fact_count; ++f) s.insert(fact_text(t, f));
  return s;
}

TEST(PddlGrounder, GripperHasExactlyTheReachableFactsAndOperators) {
  const auto g = test::load_and_ground({"gripper", "p01.pddl"});
  EXPECT_EQ(fact_names(g.task), (std::set<std::string>{"(at ball1 rooma)", "(at ball1 roomb)", "(at-robby rooma)",
                                                        "(at-robby roomb)", "(carry ball1 left)", "(carry ball1 right)",
                                                        "(free left)", "(free right)"}));
  // move 2 x 2 (a move to the same room is a no-op, still an action), pick and drop 1 x 2 x 2.
  EXPECT_EQ(g.task.operators.size(), 12U);
  EXPECT_EQ(operator_text(g.task, 0), "(move rooma rooma)");  // schema order, then arguments
}

TEST(PddlGrounder, StaticFactsAreDecidedAndPruned) {
  const auto g = test::load_and_ground({"navigation", "p01.pddl"});
  for (const auto& name : fact_names(g.task)) {
    EXPECT_EQ(name.find("connected"), std::string::npos) << name;
    EXPECT_EQ(name.find("blocked"), std::string::npos) << name;
  }
  // 9 places: the robot's position; 24 connections minus 4 blocked one way each = 20 drives.
  EXPECT_EQ(g.task.fact_count, 9);
  EXPECT_EQ(g.task.operators.size(), 20U);
  for (const auto& op : g.task.operators) {
    EXPECT_EQ(op.pre_pos.count, 1U);  // only (at robot1 ?from) is left
    EXPECT_EQ(op.pre_neg.count, 0U);  // (not (blocked ..)) and (not (= ..)) were decided
  }
}

TEST(PddlGrounder, UnreachableObjectsAreNotInstantiated) {
  // Blocks x and y only ever sit on the table in another room: nothing can pick them up, so no
  // operator mentions them, while a naive grounding would instantiate every pair.
  const std::string domain = R"((define (domain r) (:requirements :strips)
    (:predicates (here ?x) (have ?x) (linked ?x ?y))
    (:action take :parameters (?x ?y) :precondition (and (here ?x) (linked ?x ?y)) :effect (and (have ?y) (here ?y)))))";
  const std::string problem = R"((define (problem r1) (:domain r) (:objects a b c x y)
    (:init (here a) (linked a b) (linked b c) (linked x y)) (:goal (have c))))";
  auto d = parse_domain(domain, "r.pddl");
  auto p = parse_problem(problem, "r1.pddl", std::get<Domain>(d));
  Arena arena(1 << 16);
  const GroundResult r = ground(std::get<Domain>(d), std::get<Problem>(p), arena);
  ASSERT_EQ(r.status, GroundStatus::kOk) << r.message;
  std::set<std::string> ops;
  for (std::int32_t o = 0; o < static_cast<std::int32_t>(r.task.operators.size()); ++o) ops.insert(operator_text(r.task, o));
  EXPECT_EQ(ops, (std::set<std::string>{"(take a b)", "(take b c)"}));
}

TEST(PddlGrounder, ConditionalEffectsAreGrounded) {
  const auto g = test::load_and_ground({"briefcase", "p01.pddl"});
  EXPECT_TRUE(g.task.has_conditional_effects);
  std::size_t with_effects = 0;
  for (const auto& op : g.task.operators) with_effects += op.effects.count > 0 ? 1U : 0U;
  EXPECT_EQ(with_effects, 2U);  // move home office, move office home
  // Each conditional effect with an add is a relaxed action of its own.
  EXPECT_EQ(g.task.relaxed.size(), g.task.operators.size() + 4U);
}

TEST(PddlGrounder, AnArenaTooSmallNamesWhatDidNotFit) {
  const std::string dir = test::domains_dir() + "/logistics/";
  auto loaded = load_files(dir + "domain.pddl", dir + "p03.pddl");
  const auto& f = std::get<LoadedFiles>(loaded);
  // Too small for the operators while grounding: stopped early.
  Arena tiny(512);
  const GroundResult r1 = ground(f.domain, f.problem, tiny);
  EXPECT_EQ(r1.status, GroundStatus::kOutOfMemory);
  EXPECT_NE(r1.message.find("cannot hold them"), std::string::npos) << r1.message;
  EXPECT_TRUE(r1.task.operators.empty());
  // Large enough to ground, too small to copy everything in: the array is named.
  Arena big(1 << 20);
  const GroundResult ok = ground(f.domain, f.problem, big);
  ASSERT_EQ(ok.status, GroundStatus::kOk);
  const std::size_t needed = big.used();
  bool named = false;
  for (std::size_t bytes = needed / 2; bytes < needed; bytes += needed / 16 + 1) {
    Arena a(bytes);
    const GroundResult r = ground(f.domain, f.problem, a);
    ASSERT_EQ(r.status, GroundStatus::kOutOfMemory) << bytes;
    EXPECT_EQ(r.message.rfind("the arena of " + std::to_string(bytes) + " bytes cannot hold", 0), 0U) << r.message;
    named = named || r.message.find("names") != std::string::npos || r.message.find("operators") != std::string::npos;
  }
  EXPECT_TRUE(named);
  Arena exact(needed);
  EXPECT_EQ(ground(f.domain, f.problem, exact).status, GroundStatus::kOk);
}

TEST(PddlGrounder, TheSameProblemGroundsToTheSameTask) {
  const auto a = test::load_and_ground({"logistics", "p03.pddl"});
  const auto b = test::load_and_ground({"logistics", "p03.pddl"});
  ASSERT_EQ(a.task.operators.size(), b.task.operators.size());
  for (std::int32_t o = 0; o < static_cast<std::int32_t>(a.task.operators.size()); ++o) {
    EXPECT_EQ(operator_text(a.task, o), operator_text(b.task, o));
  }
  EXPECT_TRUE(std::equal(a.task.ints.begin(), a.task.ints.end(), b.task.ints.begin(), b.task.ints.end()));
}

}  // namespace
}  // namespace ringlet::pddl
