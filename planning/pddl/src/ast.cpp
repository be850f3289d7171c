#include "ringlet/pddl/ast.hpp"

namespace ringlet::pddl {
namespace {

template <typename T>
int find_named(const std::vector<T>& v, const std::string& name) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (v[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace

bool Domain::is_subtype(int type, int of) const {
  // Walks up at most types.size() parents: the parser refuses cycles, this bound is a second net.
  for (std::size_t steps = 0; type >= 0 && steps <= types.size(); ++steps) {
    if (type == of) return true;
    type = types[static_cast<std::size_t>(type)].parent;
  }
  return false;
}

int Domain::find_type(const std::string& n) const { return find_named(types, n); }
int Domain::find_predicate(const std::string& n) const { return find_named(predicates, n); }
int Domain::find_action(const std::string& n) const { return find_named(actions, n); }
int Problem::find_object(const std::string& n) const { return find_named(objects, n); }

std::string atom_text(const Domain& d, const Problem& p, const Atom& a) {
  std::string s = "(" + d.predicates[static_cast<std::size_t>(a.predicate)].name;
  for (const int o : a.args) s += " " + p.objects[static_cast<std::size_t>(o)].name;
  return s + ")";
}

}  // namespace ringlet::pddl
