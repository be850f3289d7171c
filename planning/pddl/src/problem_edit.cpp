#include "ringlet/pddl/problem_edit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ringlet/hal/portable_math.hpp"

namespace ringlet::pddl {
namespace {

// Predicates some action's effect (conditional or not) adds or deletes: the state's part of init.
std::vector<bool> fluent_predicates(const Domain& domain) {
  std::vector<bool> fluent(domain.predicates.size(), false);
  for (const Action& a : domain.actions) {
    for (const Effect& e : a.effects) {
      for (const Literal& l : e.literals) {
        if (!l.equality && l.predicate >= 0) fluent[static_cast<std::size_t>(l.predicate)] = true;
      }
    }
  }
  return fluent;
}

const Place* find_place(std::span<const Place> places, const std::string& name) {
  for (const Place& p : places) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

// Distance from (x, y) to the segment a-b.
double segment_distance(double x, double y, const Place& a, const Place& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0.0 ? ((x - a.x) * dx + (y - a.y) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return hal::portable_hypot(x - (a.x + t * dx), y - (a.y + t * dy));
}

bool binary(const Domain& d, int predicate) {
  return predicate >= 0 && d.predicates[static_cast<std::size_t>(predicate)].parameter_types.size() == 2;
}

}  // namespace

void set_initial_state(const Domain& domain, Problem& problem, const Task& task, ConstState state) {
  const std::vector<bool> fluent = fluent_predicates(domain);
  std::erase_if(problem.init, [&](const Atom& a) { return fluent[static_cast<std::size_t>(a.predicate)]; });
  for (std::int32_t f = 0; f < task.fact_count; ++f) {
    if (!is_set(state, f)) continue;
    const FactInfo& info = task.facts[static_cast<std::size_t>(f)];
    Atom atom;
    atom.predicate = info.predicate;
    for (const std::int32_t o : task.list(info.args)) atom.args.push_back(o);
    problem.init.push_back(std::move(atom));
  }
}

ObstacleEdit add_obstacle(const Domain& domain, Problem& problem, std::span<const Place> places, double x, double y,
                          double radius) {
  ObstacleEdit edit;
  const int connected = domain.find_predicate("connected");
  const int blocked = domain.find_predicate("blocked");
  if (!binary(domain, connected) || !binary(domain, blocked)) {
    edit.message = "the domain " + domain.name + " has no binary predicates connected and blocked to mark an obstacle with";
    return edit;
  }
  std::vector<Atom> on;  // the (blocked a b) atoms the obstacle stands for
  for (const Atom& a : problem.init) {
    if (a.predicate != connected) continue;
    const Place* pa = find_place(places, problem.objects[static_cast<std::size_t>(a.args[0])].name);
    const Place* pb = find_place(places, problem.objects[static_cast<std::size_t>(a.args[1])].name);
    if (pa == nullptr || pb == nullptr || segment_distance(x, y, *pa, *pb) > radius) continue;
    on.push_back(Atom{blocked, a.args});
  }
  char where[96];
  std::snprintf(where, sizeof where, "(%.2f, %.2f)", x, y);
  if (on.empty()) {
    char r[32];
    std::snprintf(r, sizeof r, "%.2f", radius);
    edit.message = std::string("no connection between places passes within ") + r + " m of " + where;
    return edit;
  }
  edit.ok = true;
  for (const Atom& b : on) {
    if (std::find(problem.init.begin(), problem.init.end(), b) != problem.init.end()) continue;
    problem.init.push_back(b);
    edit.added.push_back(b);
  }
  edit.known = edit.added.empty();
  if (edit.known) {
    edit.message = std::string("known: ") + atom_text(domain, problem, on.front()) + " at " + where;
  } else {
    for (const Atom& b : edit.added) edit.message += atom_text(domain, problem, b) + " ";
    edit.message += "added";
  }
  return edit;
}

}  // namespace ringlet::pddl
