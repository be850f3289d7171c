#include "ringlet/pddl/validator.hpp"

#include <set>

namespace ringlet::pddl {
namespace {

std::size_t ix(int i) { return static_cast<std::size_t>(i); }

class Checker {
 public:
  Checker(const Domain& d, const Problem& p) : d_(d), p_(p), state_(p.init.begin(), p.init.end()) {}

  Validation run(const std::vector<PlanStep>& plan) {
    for (std::size_t i = 0; i < plan.size(); ++i) {
      const int number = static_cast<int>(i) + 1;
      std::string why;
      if (!apply(plan[i], why)) {
        const std::string head = "step " + std::to_string(number) + " " + step_text(plan[i]) + ": ";
        Error e{plan[i].where, head + why};
        return {false, number, e.to_string()};
      }
    }
    for (const Literal& l : p_.goal) {
      if (!holds(l, {})) {
        return {false, 0,
                "the goal " + text(l, {}) + " does not hold after the plan's " + std::to_string(plan.size()) +
                    " step(s)"};
      }
    }
    return {true, 0, ""};
  }

 private:
  bool apply(const PlanStep& s, std::string& why) {
    const int a = d_.find_action(s.action);
    if (a < 0) {
      why = "unknown action " + s.action;
      return false;
    }
    const Action& act = d_.actions[ix(a)];
    if (s.args.size() != act.parameters.size()) {
      why = s.action + " takes " + std::to_string(act.parameters.size()) + " parameter(s), given " +
            std::to_string(s.args.size());
      return false;
    }
    std::vector<int> binding;
    for (std::size_t k = 0; k < s.args.size(); ++k) {
      const int o = p_.find_object(s.args[k]);
      if (o < 0) {
        why = "unknown object " + s.args[k];
        return false;
      }
      const int want = act.parameters[k].type;
      if (!d_.is_subtype(p_.objects[ix(o)].type, want)) {
        why = s.args[k] + " is of type " + d_.types[ix(p_.objects[ix(o)].type)].name + ", parameter " +
              act.parameters[k].name + " is of type " + d_.types[ix(want)].name;
        return false;
      }
      binding.push_back(o);
    }
    for (const Literal& l : act.precondition) {
      if (!holds(l, binding)) {
        why = "precondition " + text(l, binding) + " does not hold";
        return false;
      }
    }
    // Conditions on the state before the step; deletes before adds.
    std::vector<Atom> adds, dels;
    for (const Effect& e : act.effects) {
      bool fires = true;
      for (const Literal& c : e.condition) fires = fires && holds(c, binding);
      if (!fires) continue;
      for (const Literal& l : e.literals) (l.negated ? dels : adds).push_back(atom(l, binding));
    }
    for (const Atom& x : dels) state_.erase(x);
    for (const Atom& x : adds) state_.insert(x);
    return true;
  }

  static Atom atom(const Literal& l, const std::vector<int>& b) {
    Atom a{l.predicate, {}};
    for (const Term& t : l.args) a.args.push_back(t.is_variable ? b[ix(t.index)] : t.index);
    return a;
  }

  [[nodiscard]] bool holds(const Literal& l, const std::vector<int>& b) const {
    if (l.equality) {
      const Atom a = atom(l, b);
      return (a.args[0] == a.args[1]) != l.negated;
    }
    return state_.contains(atom(l, b)) != l.negated;
  }

  [[nodiscard]] std::string text(const Literal& l, const std::vector<int>& b) const {
    const Atom a = atom(l, b);
    std::string s;
    if (l.equality) {
      s = "(= " + p_.objects[ix(a.args[0])].name + " " + p_.objects[ix(a.args[1])].name + ")";
    } else {
      s = atom_text(d_, p_, a);
    }
    return l.negated ? "(not " + s + ")" : s;
  }

  const Domain& d_;
  const Problem& p_;
  std::set<Atom> state_;
};

}  // namespace

Validation validate(const Domain& domain, const Problem& problem, const std::vector<PlanStep>& plan) {
  return Checker(domain, problem).run(plan);
}

}  // namespace ringlet::pddl
