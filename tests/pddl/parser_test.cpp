// The parser: every shipped domain and problem parses into what the file says; malformed or
// inconsistent PDDL gives an error at file:line:col saying what was expected.
#include <gtest/gtest.h>

#include <string>

#include "pddl_test_support.hpp"
#include "ringlet/pddl/parser.hpp"

namespace ringlet::pddl {
namespace {

TEST(PddlParser, EveryShippedDomainAndProblemParses) {
  for (const auto& p : test::shipped_problems()) {
    const std::string dir = test::domains_dir() + "/" + p.domain + "/";
    auto loaded = load_files(dir + "domain.pddl", dir + p.problem);
    ASSERT_TRUE(std::holds_alternative<LoadedFiles>(loaded)) << std::get<Error>(loaded).to_string();
    const auto& f = std::get<LoadedFiles>(loaded);
    EXPECT_EQ(f.domain.name, p.domain);
    EXPECT_FALSE(f.domain.actions.empty());
    EXPECT_FALSE(f.problem.init.empty());
    EXPECT_FALSE(f.problem.goal.empty());
  }
}

TEST(PddlParser, LogisticsTypesFormAHierarchy) {
  const auto g = test::load_and_ground({"logistics", "p02.pddl"});
  const Domain& d = g.files.domain;
  const int truck = d.find_type("truck");
  ASSERT_GE(truck, 0);
  EXPECT_TRUE(d.is_subtype(truck, d.find_type("vehicle")));
  EXPECT_TRUE(d.is_subtype(truck, d.find_type("physobj")));
  EXPECT_TRUE(d.is_subtype(d.find_type("airport"), d.find_type("location")));
  EXPECT_FALSE(d.is_subtype(truck, d.find_type("location")));
  EXPECT_FALSE(d.is_subtype(d.find_type("location"), d.find_type("airport")));
}

TEST(PddlParser, NamesAreCaseInsensitiveAndCommentsIgnored) {
  const std::string text = R"(; a comment
(DEFINE (Domain Tiny) ; another
  (:Requirements :STRIPS)
  (:predicates (P ?x) (Q))
  (:action Go :parameters (?A) :precondition (p ?a) :effect (AND (q) (NOT (P ?A)))))
)";
  auto d = parse_domain(text, "tiny.pddl");
  ASSERT_TRUE(std::holds_alternative<Domain>(d)) << std::get<Error>(d).to_string();
  const Domain& dom = std::get<Domain>(d);
  EXPECT_EQ(dom.name, "tiny");
  ASSERT_EQ(dom.actions.size(), 1U);
  EXPECT_EQ(dom.actions[0].name, "go");
  EXPECT_EQ(dom.actions[0].precondition.size(), 1U);
  EXPECT_EQ(dom.actions[0].effects[0].literals.size(), 2U);
  EXPECT_TRUE(dom.actions[0].effects[0].literals[1].negated);
}

TEST(PddlParser, ConditionalEffectsAreKeptApart) {
  const auto g = test::load_and_ground({"briefcase", "p01.pddl"});
  const Action& move = g.files.domain.actions[static_cast<std::size_t>(g.files.domain.find_action("move"))];
  ASSERT_EQ(move.effects.size(), 3U);  // unconditional + two whens
  EXPECT_TRUE(move.effects[0].condition.empty());
  EXPECT_EQ(move.effects[1].condition.size(), 1U);
  EXPECT_EQ(move.effects[1].literals.size(), 2U);
}

struct BadCase {
  const char* what;
  const char* domain;
  const char* problem;  // nullptr: the domain must fail
  const char* expected;  // the whole "file:line:col: message" starts with this
};

constexpr const char* kGoodDomain = R"((define (domain d)
  (:requirements :strips :typing)
  (:types block - object)
  (:predicates (on ?x ?y - block) (clear ?x - block))
  (:action a :parameters (?x ?y - block) :precondition (clear ?x) :effect (on ?x ?y))))";

const BadCase kBadCases[] = {
    {"empty file", "", nullptr, "d.pddl:1:1: expected \"(\" to start the domain, found end of file"},
    {"not define", "(domain d)", nullptr, "d.pddl:1:2: expected \"define\", found \"domain\""},
    {"unclosed", "(define (domain d)", nullptr, "d.pddl:1:19: expected \")\" to end the domain, found end of file"},
    {"bad character", "(define (domain d) #)", nullptr, "d.pddl:1:20: unexpected character '#'"},
    {"unknown requirement", "(define (domain d) (:requirements :fluents))", nullptr,
     "d.pddl:1:35: requirement :fluents is not supported"},
    {"types without typing", "(define (domain d) (:types a))", nullptr,
     "d.pddl:1:28: :types needs the :typing requirement"},
    {"either", "(define (domain d) (:requirements :typing) (:types a - (either b c)))", nullptr,
     "d.pddl:1:57: \"either\" types are not supported"},
    {"type cycle", "(define (domain d) (:requirements :typing) (:types a - b b - a))", nullptr,
     "d.pddl:1:58: type b is its own ancestor"},
    {"unknown type", "(define (domain d) (:requirements :typing) (:predicates (p ?x - thing)))", nullptr,
     "d.pddl:1:65: unknown type thing"},
    {"unknown predicate",
     "(define (domain d) (:predicates (p ?x))\n (:action a :parameters (?x) :precondition (q ?x)))", nullptr,
     "d.pddl:2:45: unknown predicate q"},
    {"arity",
     "(define (domain d) (:predicates (p ?x))\n (:action a :parameters (?x ?y) :precondition (p ?x ?y)))", nullptr,
     "d.pddl:2:48: predicate p takes 1 argument(s), given 2"},
    {"unknown variable",
     "(define (domain d) (:predicates (p ?x))\n (:action a :parameters (?x) :effect (p ?z)))", nullptr,
     "d.pddl:2:41: unknown variable ?z"},
    {"negation without requirement",
     "(define (domain d) (:predicates (p ?x))\n (:action a :parameters (?x) :precondition (not (p ?x))))", nullptr,
     "d.pddl:2:45: a negative condition needs the :negative-preconditions requirement"},
    {"equality without requirement",
     "(define (domain d) (:predicates (p ?x))\n (:action a :parameters (?x ?y) :precondition (= ?x ?y)))", nullptr,
     "d.pddl:2:48: \"=\" needs the :equality requirement"},
    {"when without requirement",
     "(define (domain d) (:predicates (p ?x))\n (:action a :parameters (?x) :effect (when (p ?x) (p ?x))))", nullptr,
     "d.pddl:2:39: \"when\" needs the :conditional-effects requirement"},
    {"disjunction",
     "(define (domain d) (:predicates (p ?x))\n (:action a :parameters (?x) :precondition (or (p ?x) (p ?x))))",
     nullptr, "d.pddl:2:45: \"or\" is not supported"},
    {"type mismatch",
     "(define (domain d) (:requirements :typing) (:types a b) (:constants k - a) (:predicates (p ?x - b))\n"
     " (:action x :effect (p k)))",
     nullptr, "d.pddl:2:24: k is of type a, but argument 1 of p is of type b"},
    {"duplicate predicate", "(define (domain d) (:predicates (p) (p)))", nullptr,
     "d.pddl:1:38: predicate p is declared twice"},
    {"functions", "(define (domain d) (:functions (f)))", nullptr, "d.pddl:1:21: :functions (numeric fluents"},
    {"missing paren in action", "(define (domain d) (:predicates (p))\n (:action a :effect (p)", nullptr,
     "d.pddl:2:24: expected \")\" to end the action, found end of file"},
    // Problems against kGoodDomain.
    {"wrong domain name", kGoodDomain, "(define (problem p) (:domain e))",
     "p.pddl:1:30: the problem is for domain e, the domain file defines d"},
    {"unknown object in init", kGoodDomain,
     "(define (problem p) (:domain d) (:objects a - block)\n (:init (clear b)) (:goal (clear a)))",
     "p.pddl:2:16: unknown object b"},
    {"unknown object type", kGoodDomain, "(define (problem p) (:domain d) (:objects a - ball))",
     "p.pddl:1:47: unknown type ball"},
    {"init arity", kGoodDomain,
     "(define (problem p) (:domain d) (:objects a - block)\n (:init (on a)) (:goal (clear a)))",
     "p.pddl:2:10: predicate on takes 2 argument(s), given 1"},
    {"negated init", kGoodDomain,
     "(define (problem p) (:domain d) (:objects a - block)\n (:init (not (clear a))) (:goal (clear a)))",
     "p.pddl:2:10: the initial state lists true atoms only"},
    {"variable in goal", kGoodDomain,
     "(define (problem p) (:domain d) (:objects a - block)\n (:init) (:goal (clear ?x)))",
     "p.pddl:2:24: variable ?x where only objects are allowed"},
    {"no goal", kGoodDomain, "(define (problem p) (:domain d) (:objects a - block) (:init))",
     "p.pddl:1:62: the problem has no :goal"},
    {"duplicate object", kGoodDomain, "(define (problem p) (:domain d) (:objects a a - block))",
     "p.pddl:1:45: object a is declared twice"},
    {"metric", kGoodDomain, "(define (problem p) (:domain d) (:metric minimize (total-cost)))",
     "p.pddl:1:34: :metric is not supported"},
    {"trailing garbage", kGoodDomain, "(define (problem p) (:domain d) (:goal (and))) )",
     "p.pddl:1:48: expected end of file after the problem, found \")\""},
};

TEST(PddlParser, MalformedInputGivesALocatedError) {
  for (const BadCase& c : kBadCases) {
    SCOPED_TRACE(c.what);
    auto d = parse_domain(c.domain, "d.pddl");
    std::string got;
    if (c.problem == nullptr) {
      ASSERT_TRUE(std::holds_alternative<Error>(d)) << "the domain parsed";
      got = std::get<Error>(d).to_string();
    } else {
      ASSERT_TRUE(std::holds_alternative<Domain>(d)) << std::get<Error>(d).to_string();
      auto p = parse_problem(c.problem, "p.pddl", std::get<Domain>(d));
      ASSERT_TRUE(std::holds_alternative<Error>(p)) << "the problem parsed";
      got = std::get<Error>(p).to_string();
    }
    EXPECT_EQ(got.substr(0, std::string(c.expected).size()), c.expected) << got;
  }
}

TEST(PddlParser, DeepNestingIsRefusedNotOverflowingTheStack) {
  std::string text = "(define (domain d) (:predicates (p)) (:action a :precondition ";
  for (int i = 0; i < 100000; ++i) text += "(and ";
  auto d = parse_domain(text, "deep.pddl");
  ASSERT_TRUE(std::holds_alternative<Error>(d));
  EXPECT_NE(std::get<Error>(d).to_string().find("nested too deeply"), std::string::npos);
}

TEST(PddlParser, AMissingFileIsNamed) {
  auto r = load_files("/nonexistent/domain.pddl", "/nonexistent/p.pddl");
  ASSERT_TRUE(std::holds_alternative<Error>(r));
  EXPECT_EQ(std::get<Error>(r).to_string(), "/nonexistent/domain.pddl:0:0: cannot open the file");
}

}  // namespace
}  // namespace ringlet::pddl
