// Fuzz target: the PDDL parser, and what runs on what it accepts. The input is a domain, then
// optionally a line ";;problem" and a problem for it. Errors must be located (line and column
// from 1, the file named); a domain and problem that parse are grounded into a small arena
// (out of memory is a status) and, when the task is small, both planners run a bounded number
// of slices; every plan they return must pass the validator. Any crash, sanitizer report or
// failed check (__builtin_trap) is a finding.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "ringlet/pddl/grounder.hpp"
#include "ringlet/pddl/lama_planner.hpp"
#include "ringlet/pddl/parser.hpp"
#include "ringlet/pddl/plan_file.hpp"
#include "ringlet/pddl/regression_planner.hpp"
#include "ringlet/pddl/validator.hpp"

namespace {

using namespace ringlet::pddl;

void check_error(const Error& e, const char* file) {
  if (e.where.file != file || e.where.line < 1 || e.where.col < 1 || e.message.empty()) __builtin_trap();
}

// Grounding enumerates bindings: keep the fuzzer to tasks it can finish in milliseconds.
bool small(const Domain& d, const Problem& p) {
  if (p.objects.size() > 12) return false;
  for (const auto& a : d.actions) {
    if (a.parameters.size() > 4) return false;
  }
  return true;
}

void plan_and_validate(const Domain& d, const Problem& p) {
  Arena arena(std::size_t{1} << 16U);
  const GroundResult g = ground(d, p, arena);
  if (g.status != GroundStatus::kOk) {
    if (g.message.empty()) __builtin_trap();
    return;
  }
  const PlannerLimits limits = PlannerLimits::for_task(g.task, 2000);
  RegressionPlanner regression(limits);
  LamaPlanner lama(limits);
  for (Planner* planner : {static_cast<Planner*>(&regression), static_cast<Planner*>(&lama)}) {
    PlannerStatus s = planner->start(g.task, 12);
    for (int slice = 0; slice < 50 && s == PlannerStatus::kRunning; ++slice) s = planner->step(40);
    if (s == PlannerStatus::kFound && !validate(d, p, plan_steps(g.task, planner->plan())).valid) __builtin_trap();
    if ((s == PlannerStatus::kFailed || s == PlannerStatus::kExhausted) && *planner->reason() == '\0') __builtin_trap();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view kSeparator = ";;problem";
  const std::size_t cut = input.find(kSeparator);
  const std::string_view domain_text = input.substr(0, cut);
  auto domain = parse_domain(domain_text, "fuzz-domain.pddl");
  if (const auto* e = std::get_if<Error>(&domain)) {
    check_error(*e, "fuzz-domain.pddl");
    return 0;
  }
  if (cut == std::string_view::npos) return 0;
  const Domain& d = std::get<Domain>(domain);
  auto problem = parse_problem(input.substr(cut + kSeparator.size()), "fuzz-problem.pddl", d);
  if (const auto* e = std::get_if<Error>(&problem)) {
    check_error(*e, "fuzz-problem.pddl");
    return 0;
  }
  const Problem& p = std::get<Problem>(problem);
  if (small(d, p)) plan_and_validate(d, p);
  return 0;
}
