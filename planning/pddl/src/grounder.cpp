#include "ringlet/pddl/grounder.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <vector>

namespace ringlet::pddl {
namespace {

std::size_t ix(int i) { return static_cast<std::size_t>(i); }

struct OutOfMemory {
  std::string message;
};

/// Relaxed reachability and instantiation of one problem.
class Grounding {
 public:
  Grounding(const Domain& d, const Problem& p, std::size_t capacity) : d_(d), p_(p), capacity_(capacity) {
    fluent_.assign(d.predicates.size(), false);
    for (const auto& a : d.actions) {
      for (const auto& e : a.effects) {
        for (const auto& l : e.literals) fluent_[ix(l.predicate)] = true;
      }
    }
    by_type_.resize(d.types.size());
    for (std::size_t o = 0; o < p.objects.size(); ++o) {
      for (std::size_t t = 0; t < d.types.size(); ++t) {
        if (d.is_subtype(p.objects[o].type, static_cast<int>(t))) by_type_[t].push_back(static_cast<int>(o));
      }
    }
    known_.resize(d.predicates.size());
    for (const Atom& a : p.init) add_known(a);
    init_.insert(p.init.begin(), p.init.end());
  }

  /// Sweeps every action until no new atom becomes reachable; the last sweep's instantiations
  /// are every reachable ground action.
  void reach() {
    for (;;) {
      actions_.clear();
      pending_.clear();
      for (std::size_t a = 0; a < d_.actions.size(); ++a) {
        std::vector<int> binding(d_.actions[a].parameters.size(), -1);
        bind(static_cast<int>(a), 0, binding);
      }
      if (pending_.empty()) return;
      for (const Atom& at : pending_) add_known(at);
    }
  }

  const std::set<std::pair<int, std::vector<int>>>& actions() const { return actions_; }
  const std::set<Atom>& reachable() const { return reachable_; }
  [[nodiscard]] bool fluent(int predicate) const { return fluent_[ix(predicate)]; }
  [[nodiscard]] bool in_init(const Atom& a) const { return init_.contains(a); }

  /// The atom of literal `l` under `binding`.
  [[nodiscard]] static Atom atom_of(const Literal& l, const std::vector<int>& binding) {
    Atom a{l.predicate, {}};
    for (const Term& t : l.args) a.args.push_back(t.is_variable ? binding[ix(t.index)] : t.index);
    return a;
  }
  [[nodiscard]] static bool equality_holds(const Literal& l, const std::vector<int>& binding) {
    auto value = [&](const Term& t) { return t.is_variable ? binding[ix(t.index)] : t.index; };
    return (value(l.args[0]) == value(l.args[1])) != l.negated;
  }

 private:
  void add_known(const Atom& a) {
    if (!fluent_[ix(a.predicate)]) {
      known_[ix(a.predicate)].push_back(a.args);  // static: the init atoms only
      return;
    }
    if (reachable_.insert(a).second) {
      known_[ix(a.predicate)].push_back(a.args);
      // Facts are a fraction of the task's bytes: refuse long before they alone overflow.
      if (reachable_.size() * sizeof(FactInfo) > capacity_) {
        throw OutOfMemory{"grounding reached " + std::to_string(reachable_.size()) +
                          " facts: the arena of " + std::to_string(capacity_) + " bytes cannot hold them"};
      }
    }
  }

  // Joins the positive preconditions in order, then binds what is left from the typed objects.
  void bind(int action, std::size_t pre, std::vector<int>& binding) {
    const Action& a = d_.actions[ix(action)];
    while (pre < a.precondition.size() && (a.precondition[pre].negated || a.precondition[pre].equality)) ++pre;
    if (pre < a.precondition.size()) {
      const Literal& l = a.precondition[pre];
      for (const auto& args : known_[ix(l.predicate)]) {
        std::vector<int> saved = binding;
        bool ok = true;
        for (std::size_t i = 0; i < l.args.size() && ok; ++i) {
          const Term& t = l.args[i];
          if (!t.is_variable) {
            ok = t.index == args[i];
          } else if (binding[ix(t.index)] < 0) {
            ok = d_.is_subtype(p_.objects[ix(args[i])].type, a.parameters[ix(t.index)].type);
            binding[ix(t.index)] = args[i];
          } else {
            ok = binding[ix(t.index)] == args[i];
          }
        }
        if (ok) bind(action, pre + 1, binding);
        binding = std::move(saved);
      }
      return;
    }
    for (std::size_t v = 0; v < binding.size(); ++v) {
      if (binding[v] >= 0) continue;
      for (const int o : by_type_[ix(a.parameters[v].type)]) {
        binding[v] = o;
        bind(action, pre, binding);
      }
      binding[v] = -1;
      return;
    }
    for (const Literal& l : a.precondition) {
      if (l.equality) {
        if (!equality_holds(l, binding)) return;
      } else if (l.negated && !fluent_[ix(l.predicate)] && init_.contains(atom_of(l, binding))) {
        return;  // a static atom that stays true
      }
    }
    if (!actions_.emplace(action, binding).second) return;
    if (actions_.size() * sizeof(GroundOperator) > capacity_) {
      throw OutOfMemory{"grounding reached " + std::to_string(actions_.size()) +
                        " operators: the arena of " + std::to_string(capacity_) + " bytes cannot hold them"};
    }
    for (const Effect& e : a.effects) {
      for (const Literal& l : e.literals) {
        if (l.negated) continue;
        Atom at = atom_of(l, binding);
        if (!reachable_.contains(at)) pending_.insert(std::move(at));
      }
    }
  }

  const Domain& d_;
  const Problem& p_;
  std::size_t capacity_;
  std::vector<bool> fluent_;
  std::vector<std::vector<int>> by_type_;
  std::vector<std::vector<std::vector<int>>> known_;  // per predicate: argument lists
  std::set<Atom> reachable_;
  std::set<Atom> init_;
  std::set<Atom> pending_;
  std::set<std::pair<int, std::vector<int>>> actions_;
};

/// The task in ordinary containers, before it is copied into the arena.
struct Draft {
  std::vector<std::int32_t> ints;
  std::vector<FactInfo> facts;
  std::vector<GroundOperator> operators;
  std::vector<ConditionalEffect> effects;
  std::vector<RelaxedAction> relaxed;
  std::vector<Range> relaxed_by_pre;
  std::vector<std::int32_t> initial_facts;
  Range goal_pos, goal_neg;
  bool goal_false = false;
  bool has_conditional_effects = false;

  /// A list kept as given (arguments).
  Range push_in_order(const std::vector<int>& list) {
    const Range r{static_cast<std::uint32_t>(ints.size()), static_cast<std::uint32_t>(list.size())};
    ints.insert(ints.end(), list.begin(), list.end());
    return r;
  }

  /// A set of facts: sorted, without repeats.
  Range push(std::vector<std::int32_t> list) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    const Range r{static_cast<std::uint32_t>(ints.size()), static_cast<std::uint32_t>(list.size())};
    ints.insert(ints.end(), list.begin(), list.end());
    return r;
  }
};

class Builder {
 public:
  Builder(const Domain& d, const Problem& p, const Grounding& g) : d_(d), p_(p), g_(g) {}

  Draft build() {
    for (const Atom& a : g_.reachable()) add_fact(a);
    for (const Literal& l : p_.goal) {
      if (!l.equality) add_fact(Grounding::atom_of(l, {}));  // a goal nobody reaches still needs a number
    }
    number_facts();
    for (const auto& [atom, id] : fact_ids_) {
      if (g_.in_init(atom)) draft_.initial_facts.push_back(id);
    }
    goal();
    for (const auto& [action, binding] : g_.actions()) add_operator(action, binding);
    relax();
    return std::move(draft_);
  }

 private:
  void add_fact(const Atom& a) {
    if (fact_ids_.contains(a)) return;
    fact_ids_.emplace(a, 0);
  }

  // Numbers the facts in (predicate, arguments) order once they are all known.
  void number_facts() {
    int n = 0;
    for (auto& [atom, id] : fact_ids_) {
      id = n++;
      draft_.facts.push_back({atom.predicate, draft_.push_in_order(atom.args)});
    }
  }

  int fact(const Atom& a) {
    const auto it = fact_ids_.find(a);
    return it == fact_ids_.end() ? -1 : it->second;
  }

  void goal() {
    std::vector<std::int32_t> pos, neg;
    for (const Literal& l : p_.goal) {
      if (l.equality) {
        if (!Grounding::equality_holds(l, {})) draft_.goal_false = true;
        continue;
      }
      (l.negated ? neg : pos).push_back(fact(Grounding::atom_of(l, {})));
    }
    draft_.goal_pos = draft_.push(pos);
    draft_.goal_neg = draft_.push(neg);
  }

  /// Decides a literal as far as grounding can: 1 true, 0 false, -1 left to the state (then
  /// `id` is its fact).
  int decide(const Literal& l, const std::vector<int>& binding, int& id) {
    if (l.equality) return Grounding::equality_holds(l, binding) ? 1 : 0;
    const Atom a = Grounding::atom_of(l, binding);
    id = fact(a);
    if (!g_.fluent(l.predicate)) return g_.in_init(a) != l.negated ? 1 : 0;  // static
    if (id < 0) return l.negated ? 1 : 0;  // fluent but never reachable: false for ever
    return -1;
  }

  /// Conditions into pos/neg; false when one is false for ever.
  bool conditions(const std::vector<Literal>& ls, const std::vector<int>& b, std::vector<std::int32_t>& pos,
                  std::vector<std::int32_t>& neg) {
    for (const Literal& l : ls) {
      int id = -1;
      const int v = decide(l, b, id);
      if (v == 0) return false;
      if (v < 0) (l.negated ? neg : pos).push_back(id);
    }
    return true;
  }

  void effect_lists(const Effect& e, const std::vector<int>& b, std::vector<std::int32_t>& add,
                    std::vector<std::int32_t>& del) {
    for (const Literal& l : e.literals) {
      const int id = fact(Grounding::atom_of(l, b));
      if (id >= 0) (l.negated ? del : add).push_back(id);  // deleting what never holds does nothing
    }
  }

  static std::vector<std::int32_t> minus(std::vector<std::int32_t> a, const std::vector<std::int32_t>& b) {
    std::erase_if(a, [&](std::int32_t f) { return std::find(b.begin(), b.end(), f) != b.end(); });
    return a;
  }

  void add_operator(int action, const std::vector<int>& binding) {
    const Action& a = d_.actions[ix(action)];
    std::vector<std::int32_t> pos, neg, add, del;
    if (!conditions(a.precondition, binding, pos, neg)) return;
    for (const auto f : pos) {
      if (std::find(neg.begin(), neg.end(), f) != neg.end()) return;  // never applicable
    }
    effect_lists(a.effects[0], binding, add, del);
    GroundOperator o;
    o.action = action;
    o.args = draft_.push_in_order(binding);
    o.pre_pos = draft_.push(pos);
    o.pre_neg = draft_.push(neg);
    o.add = draft_.push(add);
    o.del = draft_.push(minus(del, add));
    o.effects.begin = static_cast<std::uint32_t>(draft_.effects.size());
    for (std::size_t k = 1; k < a.effects.size(); ++k) {
      std::vector<std::int32_t> cp, cn, ca, cd;
      if (!conditions(a.effects[k].condition, binding, cp, cn)) continue;
      effect_lists(a.effects[k], binding, ca, cd);
      draft_.effects.push_back({draft_.push(cp), draft_.push(cn), draft_.push(ca), draft_.push(minus(cd, ca))});
      draft_.has_conditional_effects = true;
    }
    o.effects.count = static_cast<std::uint32_t>(draft_.effects.size()) - o.effects.begin;
    draft_.operators.push_back(o);
  }

  void relax() {
    const auto n = static_cast<std::int32_t>(draft_.operators.size());
    for (std::int32_t op = 0; op < n; ++op) {
      const GroundOperator o = draft_.operators[ix(op)];
      auto list = [&](Range r) {
        return std::vector<std::int32_t>(draft_.ints.begin() + r.begin, draft_.ints.begin() + r.begin + r.count);
      };
      draft_.relaxed.push_back({o.pre_pos, o.add, op});
      for (std::uint32_t k = 0; k < o.effects.count; ++k) {
        const ConditionalEffect e = draft_.effects[o.effects.begin + k];
        if (e.add.count == 0) continue;
        std::vector<std::int32_t> pre = list(o.pre_pos);
        const auto cond = list(e.cond_pos);
        pre.insert(pre.end(), cond.begin(), cond.end());
        draft_.relaxed.push_back({draft_.push(pre), e.add, op});
      }
    }
    std::vector<std::vector<std::int32_t>> by_pre(draft_.facts.size());
    for (std::size_t r = 0; r < draft_.relaxed.size(); ++r) {
      const Range pre = draft_.relaxed[r].pre;
      for (std::uint32_t k = 0; k < pre.count; ++k) by_pre[ix(draft_.ints[pre.begin + k])].push_back(static_cast<std::int32_t>(r));
    }
    for (auto& l : by_pre) draft_.relaxed_by_pre.push_back(draft_.push(std::move(l)));
  }

  const Domain& d_;
  const Problem& p_;
  const Grounding& g_;
  Draft draft_;
  std::map<Atom, int> fact_ids_;
};

template <typename T>
std::span<const T> copy_in(Arena& arena, const std::vector<T>& v, const char* what) {
  auto out = arena.allocate<T>(v.size(), what);
  if (out.size() == v.size()) std::copy(v.begin(), v.end(), out.begin());
  return out;
}

/// Names as string_views into one character block of the arena.
template <typename Named>
std::span<const std::string_view> names_in(Arena& arena, const std::vector<Named>& v, const char* what) {
  std::size_t total = 0;
  for (const auto& n : v) total += n.name.size();
  auto chars = arena.allocate<char>(total, what);
  auto views = arena.allocate<std::string_view>(v.size(), what);
  if (arena.overflowed()) return {};
  std::size_t at = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    std::copy(v[i].name.begin(), v[i].name.end(), chars.begin() + static_cast<std::ptrdiff_t>(at));
    views[i] = std::string_view(chars.data() + at, v[i].name.size());
    at += v[i].name.size();
  }
  return views;
}

}  // namespace

GroundResult ground(const Domain& domain, const Problem& problem, Arena& arena) {
  arena.reset();
  GroundResult result;
  Draft draft;
  try {
    Grounding g(domain, problem, arena.capacity());
    g.reach();
    draft = Builder(domain, problem, g).build();
  } catch (const OutOfMemory& e) {
    result.status = GroundStatus::kOutOfMemory;
    result.message = e.message;
    return result;
  }
  Task& t = result.task;
  t.fact_count = static_cast<std::int32_t>(draft.facts.size());
  t.words = (t.fact_count + 63) / 64;
  if (t.words == 0) t.words = 1;
  t.ints = copy_in(arena, draft.ints, "fact lists");
  t.facts = copy_in(arena, draft.facts, "facts");
  t.operators = copy_in(arena, draft.operators, "operators");
  t.effects = copy_in(arena, draft.effects, "conditional effects");
  t.relaxed = copy_in(arena, draft.relaxed, "relaxed actions");
  t.relaxed_by_pre = copy_in(arena, draft.relaxed_by_pre, "the relaxed actions' index");
  auto initial = arena.allocate<std::uint64_t>(static_cast<std::size_t>(t.words), "the initial state");
  if (!initial.empty()) {
    for (const std::int32_t f : draft.initial_facts) set(initial, f);
  }
  t.initial = initial;
  t.goal_pos = draft.goal_pos;
  t.goal_neg = draft.goal_neg;
  t.goal_false = draft.goal_false;
  t.has_conditional_effects = draft.has_conditional_effects;
  t.object_names = names_in(arena, problem.objects, "object names");
  t.predicate_names = names_in(arena, domain.predicates, "predicate names");
  t.action_names = names_in(arena, domain.actions, "action names");
  if (arena.overflowed()) {
    result.status = GroundStatus::kOutOfMemory;
    result.message = arena.overflow();
    result.task = Task{};
  }
  return result;
}

}  // namespace ringlet::pddl
