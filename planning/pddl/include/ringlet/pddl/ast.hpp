#pragma once
// A parsed domain and problem, checked (names resolved to indices, arities and types matched):
// what the grounder and the validator read. Built on the service thread in ordinary containers.
#include <cstdint>
#include <string>
#include <vector>

#include "ringlet/pddl/error.hpp"

namespace ringlet::pddl {

/// The requirements this library understands (a bit each).
enum Requirement : std::uint32_t {
  kStrips = 1U << 0U,
  kTyping = 1U << 1U,
  kNegativePreconditions = 1U << 2U,
  kEquality = 1U << 3U,
  kConditionalEffects = 1U << 4U,
};

struct Type {
  std::string name;
  int parent = -1;  ///< -1 for "object", the root
};

struct Object {
  std::string name;
  int type = 0;
  Location where;
};

struct Predicate {
  std::string name;
  std::vector<int> parameter_types;
};

/// An argument: a parameter of the action (is_variable) or an object (a constant of the domain
/// or, in a problem, an object of the problem).
struct Term {
  bool is_variable = false;
  int index = 0;
};

/// `(p t...)`, `(not (p t...))`, `(= a b)` or `(not (= a b))`.
struct Literal {
  bool negated = false;
  bool equality = false;  ///< then args holds the two sides and predicate is -1
  int predicate = -1;
  std::vector<Term> args;
  Location where;
};

/// `(when (and cond...) (and effect...))`; an unconditional effect has no condition.
struct Effect {
  std::vector<Literal> condition;
  std::vector<Literal> literals;  ///< negated = delete
};

struct Parameter {
  std::string name;
  int type = 0;
};

struct Action {
  std::string name;
  std::vector<Parameter> parameters;
  std::vector<Literal> precondition;
  std::vector<Effect> effects;  ///< effects[0] is the unconditional part
  Location where;
};

struct Domain {
  std::string name;
  std::string file;
  std::uint32_t requirements = kStrips;
  std::vector<Type> types;        ///< types[0] is "object"
  std::vector<Object> constants;  ///< problems' objects come after these
  std::vector<Predicate> predicates;
  std::vector<Action> actions;

  [[nodiscard]] bool is_subtype(int type, int of) const;
  [[nodiscard]] int find_type(const std::string& name) const;
  [[nodiscard]] int find_predicate(const std::string& name) const;
  [[nodiscard]] int find_action(const std::string& name) const;
};

/// A ground atom: predicate and object indices (domain constants first, then problem objects).
struct Atom {
  int predicate = -1;
  std::vector<int> args;
  auto operator<=>(const Atom&) const = default;
};

struct Problem {
  std::string name;
  std::string file;
  std::vector<Object> objects;  ///< the domain's constants, then the problem's objects
  std::vector<Atom> init;
  std::vector<Literal> goal;    ///< every term an object

  [[nodiscard]] int find_object(const std::string& name) const;
};

/// "(on a b)" from names.
[[nodiscard]] std::string atom_text(const Domain& d, const Problem& p, const Atom& a);

}  // namespace ringlet::pddl
