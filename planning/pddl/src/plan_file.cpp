#include "ringlet/pddl/plan_file.hpp"

#include "ringlet/pddl/lexer.hpp"

namespace ringlet::pddl {

Parsed<std::vector<PlanStep>> parse_plan(std::string_view text, const std::string& file) {
  std::vector<Token> tokens;
  Error e;
  if (!tokenize(text, file, tokens, e)) return e;
  std::vector<PlanStep> steps;
  auto expected = [&](const Token& t, const std::string& what) {
    return Error{{file, t.line, t.col}, "expected " + what + ", found " + describe(t)};
  };
  std::size_t i = 0;
  while (tokens[i].kind != TokenKind::kEnd) {
    if (tokens[i].kind != TokenKind::kOpen) return expected(tokens[i], "\"(\" to start a plan step");
    ++i;
    if (tokens[i].kind != TokenKind::kName) return expected(tokens[i], "an action's name");
    PlanStep s{tokens[i].text, {}, {file, tokens[i].line, tokens[i].col}};
    ++i;
    while (tokens[i].kind == TokenKind::kName || tokens[i].kind == TokenKind::kNumber) s.args.push_back(tokens[i++].text);
    if (tokens[i].kind != TokenKind::kClose) return expected(tokens[i], "an object or \")\"");
    ++i;
    steps.push_back(std::move(s));
  }
  return steps;
}

std::vector<PlanStep> plan_steps(const Task& task, std::span<const std::int32_t> plan) {
  std::vector<PlanStep> steps;
  for (const std::int32_t op : plan) {
    const GroundOperator& o = task.operators[static_cast<std::size_t>(op)];
    PlanStep s{std::string(task.action_names[static_cast<std::size_t>(o.action)]), {}, {}};
    for (const std::int32_t a : task.list(o.args)) s.args.emplace_back(task.object_names[static_cast<std::size_t>(a)]);
    steps.push_back(std::move(s));
  }
  return steps;
}

std::string step_text(const PlanStep& step) {
  std::string s = "(" + step.action;
  for (const auto& a : step.args) s += " " + a;
  return s + ")";
}

}  // namespace ringlet::pddl
