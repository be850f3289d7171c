#pragma once
// The grounded task the planners read: flat, read-only arrays in an Arena (no pointer into
// ordinary containers), so the service thread can build it and hand it to the cycle whole.
// Facts are numbered 0 .. fact_count-1 and a state is a bit set of `words` 64-bit words.
// Static facts (true or false in every state) are gone: their conditions were decided while
// grounding.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace ringlet::pddl {

/// A slice of Task::ints (or of another array).
struct Range {
  std::uint32_t begin = 0;
  std::uint32_t count = 0;
};

struct ConditionalEffect {
  Range cond_pos, cond_neg, add, del;
};

/// One ground action. STRIPS semantics: deletes first, then adds (so del excludes add).
struct GroundOperator {
  std::int32_t action = 0;  ///< the schema: index of the domain's action
  Range args;               ///< object indices
  Range pre_pos, pre_neg, add, del;
  Range effects;            ///< into Task::effects: its conditional effects
};

/// The delete relaxation's view of an operator or of one of its conditional effects (op's
/// preconditions plus the effect's positive conditions): what h_FF propagates.
struct RelaxedAction {
  Range pre, add;
  std::int32_t op = 0;
};

struct FactInfo {
  std::int32_t predicate = 0;
  Range args;  ///< object indices
};

struct Task {
  std::int32_t fact_count = 0;
  std::int32_t words = 0;  ///< 64-bit words per state
  std::span<const std::int32_t> ints;  ///< every list below points in here
  std::span<const FactInfo> facts;
  std::span<const GroundOperator> operators;
  std::span<const ConditionalEffect> effects;
  std::span<const RelaxedAction> relaxed;
  std::span<const Range> relaxed_by_pre;  ///< per fact: the relaxed actions it is a condition of
  std::span<const std::uint64_t> initial;
  Range goal_pos, goal_neg;
  bool goal_false = false;  ///< an equality in the goal is false: no plan can exist
  bool has_conditional_effects = false;
  std::span<const std::string_view> object_names, predicate_names, action_names;

  [[nodiscard]] std::span<const std::int32_t> list(Range r) const noexcept { return ints.subspan(r.begin, r.count); }
  [[nodiscard]] std::size_t operator_count() const noexcept { return operators.size(); }
};

using State = std::span<std::uint64_t>;
using ConstState = std::span<const std::uint64_t>;

[[nodiscard]] inline bool is_set(ConstState s, std::int32_t fact) noexcept {
  const auto f = static_cast<std::uint32_t>(fact);
  return ((s[f >> 6U] >> (f & 63U)) & 1U) != 0;
}
inline void set(State s, std::int32_t fact) noexcept {
  const auto f = static_cast<std::uint32_t>(fact);
  s[f >> 6U] |= std::uint64_t{1} << (f & 63U);
}
inline void clear(State s, std::int32_t fact) noexcept {
  const auto f = static_cast<std::uint32_t>(fact);
  s[f >> 6U] &= ~(std::uint64_t{1} << (f & 63U));
}

[[nodiscard]] bool all_true(ConstState s, std::span<const std::int32_t> facts) noexcept;
[[nodiscard]] bool none_true(ConstState s, std::span<const std::int32_t> facts) noexcept;
[[nodiscard]] bool applicable(const Task& t, std::int32_t op, ConstState s) noexcept;
/// `to` = the state after `op` in `from` (different buffers of t.words words).
void apply(const Task& t, std::int32_t op, ConstState from, State to) noexcept;
[[nodiscard]] bool goal_holds(const Task& t, ConstState s) noexcept;

/// "(on a b)", "(move r1 a b)": for printing and messages (allocates; not for the cycle).
[[nodiscard]] std::string fact_text(const Task& t, std::int32_t fact);
[[nodiscard]] std::string operator_text(const Task& t, std::int32_t op);

}  // namespace ringlet::pddl
