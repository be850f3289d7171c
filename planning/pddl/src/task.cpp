#include "ringlet/pddl/task.hpp"

#include <algorithm>

namespace ringlet::pddl {

bool all_true(ConstState s, std::span<const std::int32_t> facts) noexcept {
  return std::all_of(facts.begin(), facts.end(), [&](std::int32_t f) { return is_set(s, f); });
}

bool none_true(ConstState s, std::span<const std::int32_t> facts) noexcept {
  return std::none_of(facts.begin(), facts.end(), [&](std::int32_t f) { return is_set(s, f); });
}

bool applicable(const Task& t, std::int32_t op, ConstState s) noexcept {
  const GroundOperator& o = t.operators[static_cast<std::size_t>(op)];
  return all_true(s, t.list(o.pre_pos)) && none_true(s, t.list(o.pre_neg));
}

void apply(const Task& t, std::int32_t op, ConstState from, State to) noexcept {
  const GroundOperator& o = t.operators[static_cast<std::size_t>(op)];
  std::copy(from.begin(), from.end(), to.begin());
  // Conditions are read in `from`, the state before the action; every delete before every add.
  const auto effects = t.effects.subspan(o.effects.begin, o.effects.count);
  auto fires = [&](const ConditionalEffect& e) {
    return all_true(from, t.list(e.cond_pos)) && none_true(from, t.list(e.cond_neg));
  };
  for (const std::int32_t f : t.list(o.del)) clear(to, f);
  for (const auto& e : effects) {
    if (fires(e)) {
      for (const std::int32_t f : t.list(e.del)) clear(to, f);
    }
  }
  for (const std::int32_t f : t.list(o.add)) set(to, f);
  for (const auto& e : effects) {
    if (fires(e)) {
      for (const std::int32_t f : t.list(e.add)) set(to, f);
    }
  }
}

bool goal_holds(const Task& t, ConstState s) noexcept {
  return !t.goal_false && all_true(s, t.list(t.goal_pos)) && none_true(s, t.list(t.goal_neg));
}

namespace {
std::string name_with_args(std::string_view head, const Task& t, Range args) {
  std::string s = "(" + std::string(head);
  for (const std::int32_t o : t.list(args)) s += " " + std::string(t.object_names[static_cast<std::size_t>(o)]);
  return s + ")";
}
}  // namespace

std::string fact_text(const Task& t, std::int32_t fact) {
  const FactInfo& f = t.facts[static_cast<std::size_t>(fact)];
  return name_with_args(t.predicate_names[static_cast<std::size_t>(f.predicate)], t, f.args);
}

std::string operator_text(const Task& t, std::int32_t op) {
  const GroundOperator& o = t.operators[static_cast<std::size_t>(op)];
  return name_with_args(t.action_names[static_cast<std::size_t>(o.action)], t, o.args);
}

}  // namespace ringlet::pddl
