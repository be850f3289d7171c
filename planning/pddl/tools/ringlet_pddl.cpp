// ringlet-pddl: plan for a PDDL domain and problem with the library's planners (sliced exactly
// as in the cycle), print the plan and the statistics, or check a plan with --validate.
// Exit codes: 0 plan found (or the plan given is valid), 1 no plan (or an invalid plan),
// 2 bad input (arguments, files, PDDL, a task beyond the configured memory).
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

#include "ringlet/pddl/grounder.hpp"
#include "ringlet/pddl/lama_planner.hpp"
#include "ringlet/pddl/loader.hpp"
#include "ringlet/pddl/plan_file.hpp"
#include "ringlet/pddl/regression_planner.hpp"
#include "ringlet/pddl/validator.hpp"

namespace {

using namespace ringlet::pddl;
using Clock = std::chrono::steady_clock;  // reporting only: no decision depends on it

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

int validate_file(const LoadedFiles& files, const std::string& path) {
  auto text = read_text_file(path);
  if (auto* e = std::get_if<Error>(&text)) {
    std::cerr << "ringlet-pddl: " << e->to_string() << "\n";
    return 2;
  }
  auto steps = parse_plan(std::get<std::string>(text), path);
  if (auto* e = std::get_if<Error>(&steps)) {
    std::cerr << "ringlet-pddl: " << e->to_string() << "\n";
    return 2;
  }
  const auto& plan = std::get<std::vector<PlanStep>>(steps);
  const Validation v = validate(files.domain, files.problem, plan);
  if (!v.valid) {
    std::cout << "plan invalid: " << v.reason << "\n";
    return 1;
  }
  std::cout << "plan valid: " << plan.size() << " step(s), cost " << plan.size() << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Plan for a PDDL domain and problem (STRIPS with :typing, :negative-preconditions, :equality, "
               ":conditional-effects), or validate a plan.\nExit codes: 0 plan found / plan valid, 1 no plan / "
               "plan invalid, 2 bad input.",
               "ringlet-pddl"};
  std::string domain_path, problem_path, planner_name = "lama", validate_path;
  std::int32_t depth = kNoHorizon;
  std::uint32_t budget = 1000;
  std::size_t arena_bytes = std::size_t{64} << 20U;
  std::size_t nodes = 1000000;
  std::int32_t restarts = 4;
  app.add_option("domain", domain_path, "the domain file")->required();
  app.add_option("problem", problem_path, "the problem file")->required();
  app.add_option("--planner", planner_name, "lama (greedy h_FF + restarting weighted A*) or regression (optimal)")
      ->check(CLI::IsMember({"lama", "regression"}))
      ->capture_default_str();
  app.add_option("--depth", depth, "horizon: plans of at most N actions (default: any length)")
      ->check(CLI::Range(0, 1 << 30));
  app.add_option("--budget", budget, "work units (node expansions) per slice, as the planner task would run it")
      ->check(CLI::Range(1U, 1U << 30U))
      ->capture_default_str();
  app.add_option("--validate", validate_path, "check this plan (one \"(action object...)\" per line) instead of planning");
  app.add_option("--arena-bytes", arena_bytes, "memory for the grounded task")->check(CLI::Range(std::size_t{1}, std::size_t{1} << 34U))
      ->capture_default_str();
  app.add_option("--nodes", nodes, "search nodes the planner holds at most")->check(CLI::Range(std::size_t{1}, std::size_t{1} << 28U))
      ->capture_default_str();
  app.add_option("--restarts", restarts, "lama: weighted A* restarts after the first plan (weights 5, 3, 2, 1)")
      ->check(CLI::Range(0, 4))
      ->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }

  const auto t_parse = Clock::now();
  auto loaded = load_files(domain_path, problem_path);
  if (auto* e = std::get_if<Error>(&loaded)) {
    std::cerr << "ringlet-pddl: " << e->to_string() << "\n";
    return 2;
  }
  const auto& files = std::get<LoadedFiles>(loaded);
  if (!validate_path.empty()) return validate_file(files, validate_path);
  const double parse_ms = ms_since(t_parse);

  const auto t_ground = Clock::now();
  Arena arena(arena_bytes);
  const GroundResult g = ground(files.domain, files.problem, arena);
  if (g.status != GroundStatus::kOk) {
    std::cerr << "ringlet-pddl: out of memory: " << g.message << " (raise --arena-bytes)\n";
    return 2;
  }
  const double ground_ms = ms_since(t_ground);

  const PlannerLimits limits = PlannerLimits::for_task(g.task, nodes);
  std::unique_ptr<Planner> planner;
  if (planner_name == "regression") {
    planner = std::make_unique<RegressionPlanner>(limits);
  } else {
    LamaOptions options;
    options.restarts = restarts;
    planner = std::make_unique<LamaPlanner>(limits, options);
  }
  const auto t_search = Clock::now();
  PlannerStatus s = planner->start(g.task, depth);
  while (s == PlannerStatus::kRunning) s = planner->step(budget);
  const double search_ms = ms_since(t_search);
  const PlannerStats& st = planner->stats();

  int rc = 0;
  if (s == PlannerStatus::kFound) {
    const auto steps = plan_steps(g.task, planner->plan());
    for (const auto& step : steps) std::cout << step_text(step) << "\n";
    const Validation v = validate(files.domain, files.problem, steps);
    std::cout << "; " << planner->name() << ": plan found, length " << st.plan_length << ", cost " << st.plan_cost
              << (v.valid ? " (validated)" : " (INVALID: " + v.reason + ")") << "\n";
    if (!v.valid) rc = 1;
  } else {
    std::cout << "; " << planner->name() << ": no plan (" << to_string(s) << "): " << planner->reason() << "\n";
    rc = 1;
  }
  if (*planner->reason() != '\0' && s == PlannerStatus::kFound) std::cout << "; note: " << planner->reason() << "\n";
  std::cout << "; expansions " << st.expansions << ", generated " << st.generated << ", evaluations " << st.evaluations
            << ", plans " << st.plans_found << "\n";
  std::cout << "; slices " << st.slices << " of at most " << budget << " units (largest " << st.max_units_in_slice
            << ")\n";
  std::cout << "; task: " << g.task.fact_count << " facts, " << g.task.operators.size() << " operators, arena "
            << arena.used() << " of " << arena.capacity() << " bytes\n";
  std::printf("; time: parse %.2f ms, ground %.2f ms, search %.2f ms\n", parse_ms, ground_ms, search_ms);
  return rc;
}
