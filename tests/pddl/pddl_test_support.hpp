#pragma once
// Shared by the PDDL tests: the shipped problems, loading and grounding them, running a planner
// to the end in slices, and checking a plan with the validator.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "ringlet/pddl/grounder.hpp"
#include "ringlet/pddl/loader.hpp"
#include "ringlet/pddl/planner.hpp"
#include "ringlet/pddl/validator.hpp"

namespace ringlet::pddl::test {

inline std::string domains_dir() { return RINGLET_PDDL_DOMAINS_DIR; }

struct ShippedProblem {
  std::string domain;   ///< folder under planning/pddl/domains
  std::string problem;  ///< file name in it
};

/// Every shipped problem.
inline std::vector<ShippedProblem> shipped_problems() {
  return {{"gripper", "p01.pddl"},     {"gripper", "p02.pddl"},     {"gripper", "p04.pddl"},
          {"gripper", "p08.pddl"},     {"blocksworld", "p01.pddl"}, {"blocksworld", "p02.pddl"},
          {"blocksworld", "p03.pddl"}, {"logistics", "p01.pddl"},   {"logistics", "p02.pddl"},
          {"logistics", "p03.pddl"},   {"navigation", "p01.pddl"},  {"navigation", "p02.pddl"},
          {"navigation", "p03.pddl"},  {"briefcase", "p01.pddl"},   {"briefcase", "p02.pddl"}};
}

/// A loaded and grounded problem; the task lives in `arena`.
struct Grounded {
  LoadedFiles files;
  std::unique_ptr<Arena> arena;
  Task task;
};

inline Grounded load_and_ground(const ShippedProblem& p, std::size_t arena_bytes = std::size_t{16} << 20U) {
  const std::string dir = domains_dir() + "/" + p.domain + "/";
  auto loaded = load_files(dir + "domain.pddl", dir + p.problem);
  if (auto* e = std::get_if<Error>(&loaded)) ADD_FAILURE() << e->to_string();
  Grounded g{std::move(std::get<LoadedFiles>(loaded)), std::make_unique<Arena>(arena_bytes), {}};
  const GroundResult r = ground(g.files.domain, g.files.problem, *g.arena);
  EXPECT_EQ(r.status, GroundStatus::kOk) << r.message;
  g.task = r.task;
  return g;
}

/// Runs a started planner to the end in slices of `units`.
inline PlannerStatus run(Planner& planner, std::uint32_t units) {
  PlannerStatus s = planner.status();
  for (int guard = 0; s == PlannerStatus::kRunning && guard < 100000000; ++guard) s = planner.step(units);
  return s;
}

/// The validator's verdict on a planner's plan.
inline Validation check(const Grounded& g, std::span<const std::int32_t> plan) {
  return validate(g.files.domain, g.files.problem, plan_steps(g.task, plan));
}

}  // namespace ringlet::pddl::test
