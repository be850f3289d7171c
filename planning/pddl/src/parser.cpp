// A recursive-descent parser over the token list. Errors are thrown as ParseFailure inside this
// file only and returned as an Error by the public functions.
#include "ringlet/pddl/parser.hpp"

#include <fstream>
#include <sstream>
#include <utility>

#include "ringlet/pddl/lexer.hpp"

namespace ringlet::pddl {
namespace {

struct ParseFailure {
  Error error;
};

constexpr int kMaxNesting = 64;  // deeper (and (and ...)) is refused: the stack stays bounded

std::size_t ix(int i) { return static_cast<std::size_t>(i); }

class Cursor {
 public:
  Cursor(std::vector<Token> tokens, std::string file) : tokens_(std::move(tokens)), file_(std::move(file)) {}

  [[nodiscard]] const Token& peek(std::size_t ahead = 0) const {
    return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)];
  }
  const Token& next() {
    const Token& t = peek();
    if (pos_ < tokens_.size() - 1) ++pos_;
    return t;
  }
  [[noreturn]] void fail(const Token& at, const std::string& message) const {
    throw ParseFailure{{{file_, at.line, at.col}, message}};
  }
  [[noreturn]] void expected(const std::string& what) const {
    fail(peek(), "expected " + what + ", found " + describe(peek()));
  }
  void open(const std::string& what) {
    if (peek().kind != TokenKind::kOpen) expected("\"(\" " + what);
    next();
  }
  void close(const std::string& what) {
    if (peek().kind != TokenKind::kClose) expected("\")\" " + what);
    next();
  }
  const Token& name(const std::string& what) {
    if (peek().kind != TokenKind::kName && peek().kind != TokenKind::kNumber) expected(what);
    return next();
  }
  void word(const std::string& w) {
    if (peek().kind != TokenKind::kName || peek().text != w) expected("\"" + w + "\"");
    next();
  }
  [[nodiscard]] Location at(const Token& t) const { return {file_, t.line, t.col}; }
  [[nodiscard]] const std::string& file() const { return file_; }

 private:
  std::vector<Token> tokens_;
  std::string file_;
  std::size_t pos_ = 0;
};

Cursor make_cursor(std::string_view text, const std::string& file) {
  std::vector<Token> tokens;
  Error e;
  if (!tokenize(text, file, tokens, e)) throw ParseFailure{e};
  return {std::move(tokens), file};
}

const char* requirement_name(std::uint32_t r) {
  switch (r) {
    case kTyping: return ":typing";
    case kNegativePreconditions: return ":negative-preconditions";
    case kEquality: return ":equality";
    case kConditionalEffects: return ":conditional-effects";
    default: return ":strips";
  }
}

/// Reads a typed list "a b - t c - u d" up to ")" (not consumed): names (or variables) with the
/// type token that follows them, nullptr-like (-1 line) for untyped ones.
struct TypedName {
  Token name;
  Token type;  // kind kEnd when untyped
};
std::vector<TypedName> typed_list(Cursor& c, TokenKind kind, const std::string& what, std::uint32_t requirements) {
  std::vector<TypedName> out;
  std::size_t untyped_from = 0;
  while (c.peek().kind != TokenKind::kClose) {
    if (c.peek().kind == TokenKind::kDash) {
      const Token& dash = c.next();
      if ((requirements & kTyping) == 0) c.fail(dash, "a type (\"- type\") needs the :typing requirement");
      if (untyped_from == out.size()) c.fail(dash, "expected " + what + " before \"-\"");
      if (c.peek().kind == TokenKind::kOpen) {
        if (c.peek(1).text == "either") c.fail(c.peek(1), "\"either\" types are not supported: declare a common supertype");
        c.expected("a type name");
      }
      const Token type = c.name("a type name after \"-\"");
      for (std::size_t i = untyped_from; i < out.size(); ++i) out[i].type = type;
      untyped_from = out.size();
      continue;
    }
    if (c.peek().kind != kind && !(kind == TokenKind::kName && c.peek().kind == TokenKind::kNumber)) {
      c.expected(what);
    }
    out.push_back({c.next(), Token{}});
  }
  return out;
}

class DomainParser {
 public:
  DomainParser(Cursor& c, Domain& d) : c_(c), d_(d) {}

  void parse() {
    c_.open("to start the domain");
    c_.word("define");
    c_.open("before \"domain\"");
    c_.word("domain");
    d_.name = c_.name("the domain's name").text;
    c_.close("after the domain's name");
    d_.types.push_back({"object", -1});
    while (c_.peek().kind == TokenKind::kOpen) {
      c_.next();
      const Token& section = c_.peek();
      if (section.kind != TokenKind::kKeyword) c_.expected("a section such as :requirements, :types, :predicates or :action");
      c_.next();
      if (section.text == ":requirements") {
        requirements();
      } else if (section.text == ":types") {
        types();
      } else if (section.text == ":constants") {
        constants();
      } else if (section.text == ":predicates") {
        predicates();
      } else if (section.text == ":action") {
        action();
      } else if (section.text == ":functions") {
        c_.fail(section, ":functions (numeric fluents, action costs) is not supported");
      } else if (section.text == ":derived" || section.text == ":durative-action") {
        c_.fail(section, section.text + " is not supported (STRIPS subset)");
      } else {
        c_.fail(section, "unknown domain section " + section.text);
      }
    }
    c_.close("to end the domain");
    if (c_.peek().kind != TokenKind::kEnd) c_.expected("end of file after the domain");
  }

 private:
  void requirements() {
    while (c_.peek().kind == TokenKind::kKeyword) {
      const Token& r = c_.next();
      if (r.text == ":strips") {
        d_.requirements |= kStrips;
      } else if (r.text == ":typing") {
        d_.requirements |= kTyping;
      } else if (r.text == ":negative-preconditions") {
        d_.requirements |= kNegativePreconditions;
      } else if (r.text == ":equality") {
        d_.requirements |= kEquality;
      } else if (r.text == ":conditional-effects") {
        d_.requirements |= kConditionalEffects;
      } else {
        c_.fail(r, "requirement " + r.text +
                       " is not supported (supported: :strips :typing :negative-preconditions :equality "
                       ":conditional-effects)");
      }
    }
    c_.close("after the requirements (each a keyword such as :typing)");
  }

  void need(std::uint32_t requirement, const Token& where, const std::string& what) {
    if ((d_.requirements & requirement) == 0) {
      c_.fail(where, what + " needs the " + std::string(requirement_name(requirement)) + " requirement");
    }
  }

  void types() {
    if ((d_.requirements & kTyping) == 0) c_.fail(c_.peek(), ":types needs the :typing requirement");
    const auto list = typed_list(c_, TokenKind::kName, "a type name", d_.requirements);
    c_.close("after the types");
    // Declare every name first (a parent may come later in the list), then link parents.
    auto declare = [&](const Token& t) {
      if (d_.find_type(t.text) < 0) d_.types.push_back({t.text, 0});
    };
    for (const auto& tn : list) {
      declare(tn.name);
      if (tn.type.kind != TokenKind::kEnd) declare(tn.type);
    }
    for (const auto& tn : list) {
      if (tn.name.text == "object") {
        if (tn.type.kind != TokenKind::kEnd) c_.fail(tn.name, "\"object\" is the root type and has no parent");
        continue;
      }
      const int t = d_.find_type(tn.name.text);
      const int parent = tn.type.kind == TokenKind::kEnd ? 0 : d_.find_type(tn.type.text);
      auto& type = d_.types[ix(t)];
      if (type.parent != 0 && type.parent != parent) c_.fail(tn.name, "type " + tn.name.text + " is given two parents");
      type.parent = parent;
      if (d_.is_subtype(parent, t) || parent == t) c_.fail(tn.name, "type " + tn.name.text + " is its own ancestor (a cycle)");
    }
  }

  int type_of(const TypedName& tn) {
    if (tn.type.kind == TokenKind::kEnd) return 0;
    const int t = d_.find_type(tn.type.text);
    if (t < 0) c_.fail(tn.type, "unknown type " + tn.type.text);
    return t;
  }

  void constants() {
    for (const auto& tn : typed_list(c_, TokenKind::kName, "a constant's name", d_.requirements)) {
      for (const auto& o : d_.constants) {
        if (o.name == tn.name.text) c_.fail(tn.name, "constant " + tn.name.text + " is declared twice");
      }
      d_.constants.push_back({tn.name.text, type_of(tn), c_.at(tn.name)});
    }
    c_.close("after the constants");
  }

  void predicates() {
    while (c_.peek().kind == TokenKind::kOpen) {
      c_.next();
      const Token& n = c_.name("a predicate's name");
      if (d_.find_predicate(n.text) >= 0) c_.fail(n, "predicate " + n.text + " is declared twice");
      Predicate p{n.text, {}};
      for (const auto& tn : typed_list(c_, TokenKind::kVariable, "a parameter (?name)", d_.requirements)) {
        p.parameter_types.push_back(type_of(tn));
      }
      c_.close("after the predicate's parameters");
      d_.predicates.push_back(std::move(p));
    }
    c_.close("after the predicates");
  }

  void action() {
    const Token& n = c_.name("the action's name");
    if (d_.find_action(n.text) >= 0) c_.fail(n, "action " + n.text + " is declared twice");
    Action a;
    a.name = n.text;
    a.where = c_.at(n);
    a.effects.emplace_back();
    while (c_.peek().kind == TokenKind::kKeyword) {
      const Token& k = c_.next();
      if (k.text == ":parameters") {
        c_.open("after :parameters");
        for (const auto& tn : typed_list(c_, TokenKind::kVariable, "a parameter (?name)", d_.requirements)) {
          for (const auto& p : a.parameters) {
            if (p.name == tn.name.text) c_.fail(tn.name, "parameter " + tn.name.text + " is declared twice");
          }
          a.parameters.push_back({tn.name.text, type_of(tn)});
        }
        c_.close("after the parameters");
      } else if (k.text == ":precondition") {
        condition(a.parameters, a.precondition, 0);
      } else if (k.text == ":effect") {
        std::vector<Effect> whens;
        effect(a.parameters, a.effects[0], &whens, 0);
        for (auto& w : whens) a.effects.push_back(std::move(w));
      } else {
        c_.fail(k, "expected :parameters, :precondition or :effect, found " + k.text);
      }
    }
    c_.close("to end the action");
    d_.actions.push_back(std::move(a));
  }

  /// Opens a condition or an effect. "()" and "(and x...)" (each x read by `part` one level
  /// deeper) are consumed whole: true. Otherwise false, the cursor just after "(". The depth
  /// bound keeps the recursion's stack small whatever the input.
  template <typename Part>
  bool conjunction(const char* plural, const char* one, int depth, Part part) {
    if (depth > kMaxNesting) c_.fail(c_.peek(), std::string(plural) + " nested too deeply");
    c_.open(std::string("to start ") + one);
    if (c_.peek().kind == TokenKind::kClose) {
      c_.next();
      return true;
    }
    if (c_.peek().kind != TokenKind::kName || c_.peek().text != "and") return false;
    c_.next();
    while (c_.peek().kind != TokenKind::kClose) part(depth + 1);
    c_.next();
    return true;
  }

 public:
  /// A goal description: and / not / = / an atom; `()` is the empty conjunction.
  void condition(const std::vector<Parameter>& scope, std::vector<Literal>& out, int depth) {
    if (conjunction("conditions", "a condition", depth, [&](int d) { condition(scope, out, d); })) return;
    const Token& head = c_.peek();
    if (head.kind == TokenKind::kName &&
        (head.text == "or" || head.text == "imply" || head.text == "exists" || head.text == "forall")) {
      c_.fail(head, "\"" + head.text + "\" is not supported (STRIPS subset: a conjunction of literals)");
    }
    out.push_back(literal_body(scope, true));
  }

  /// After "(": an atom, "= a b" or "not (...)", through the closing ")".
  Literal literal_body(const std::vector<Parameter>& scope, bool negation_is_precondition) {
    const Token& head = c_.peek();
    Literal l;
    l.where = c_.at(head);
    if (head.kind == TokenKind::kName && head.text == "not") {
      c_.next();
      c_.open("after \"not\"");
      l = literal_body(scope, negation_is_precondition);
      if (l.negated) c_.fail(head, "double negation is not supported");
      if (!l.equality && negation_is_precondition) need(kNegativePreconditions, head, "a negative condition");
      l.negated = true;
      l.where = c_.at(head);
      c_.close("after the negated literal");
      return l;
    }
    if (head.kind == TokenKind::kName && head.text == "=") {
      need(kEquality, head, "\"=\"");
      c_.next();
      l.equality = true;
      l.args.push_back(term(scope));
      l.args.push_back(term(scope));
      c_.close("after the two sides of \"=\"");
      return l;
    }
    atom_body(scope, l);
    return l;
  }

  /// "p t..." and ")": resolves the predicate, each term, the arity and the types.
  void atom_body(const std::vector<Parameter>& scope, Literal& l) {
    const Token& p = c_.name("a predicate's name");
    l.predicate = d_.find_predicate(p.text);
    if (l.predicate < 0) c_.fail(p, "unknown predicate " + p.text);
    const auto& pred = d_.predicates[ix(l.predicate)];
    std::vector<Token> where;
    while (c_.peek().kind != TokenKind::kClose) {
      where.push_back(c_.peek());
      l.args.push_back(term(scope));
    }
    if (l.args.size() != pred.parameter_types.size()) {
      c_.fail(p, "predicate " + p.text + " takes " + std::to_string(pred.parameter_types.size()) +
                     " argument(s), given " + std::to_string(l.args.size()));
    }
    for (std::size_t i = 0; i < l.args.size(); ++i) {
      const Term& t = l.args[i];
      const int want = pred.parameter_types[i];
      const int have = t.is_variable ? scope[ix(t.index)].type : objects()[ix(t.index)].type;
      // A variable may be of a supertype (its binding is checked when grounding); an object must fit.
      const bool fits = d_.is_subtype(have, want) || (t.is_variable && d_.is_subtype(want, have));
      if (!fits) {
        c_.fail(where[i], where[i].text + " is of type " + d_.types[ix(have)].name + ", but argument " +
                               std::to_string(i + 1) + " of " + p.text + " is of type " + d_.types[ix(want)].name);
      }
    }
    c_.next();
  }

  Term term(const std::vector<Parameter>& scope) {
    const Token& t = c_.peek();
    if (t.kind == TokenKind::kVariable) {
      for (std::size_t i = 0; i < scope.size(); ++i) {
        if (scope[i].name == t.text) {
          c_.next();
          return {true, static_cast<int>(i)};
        }
      }
      c_.fail(t, scope.empty() ? "variable " + t.text + " where only objects are allowed"
                               : "unknown variable " + t.text + " (not a parameter of the action)");
    }
    if (t.kind != TokenKind::kName && t.kind != TokenKind::kNumber) c_.expected("a variable or an object");
    const auto& objs = objects();
    for (std::size_t i = 0; i < objs.size(); ++i) {
      if (objs[i].name == t.text) {
        c_.next();
        return {false, static_cast<int>(i)};
      }
    }
    c_.fail(t, (problem_objects_ != nullptr ? "unknown object " : "unknown constant ") + t.text);
  }

  void use_problem_objects(const std::vector<Object>* objects) { problem_objects_ = objects; }

 private:
  /// Literals go to `out`; a "when" goes to `whens` (nullptr inside a "when": no nesting).
  void effect(const std::vector<Parameter>& scope, Effect& out, std::vector<Effect>* whens, int depth) {
    if (conjunction("effects", "an effect", depth, [&](int d) { effect(scope, out, whens, d); })) return;
    const Token& head = c_.peek();
    if (head.kind == TokenKind::kName && head.text == "when") {
      need(kConditionalEffects, head, "\"when\"");
      if (whens == nullptr) c_.fail(head, "\"when\" inside \"when\" is not supported");
      c_.next();
      Effect e;
      condition(scope, e.condition, depth + 1);
      effect(scope, e, nullptr, depth + 1);
      c_.close("after the effect of \"when\"");
      whens->push_back(std::move(e));
      return;
    }
    if (head.kind == TokenKind::kName && (head.text == "forall" || head.text == "increase")) {
      c_.fail(head, "\"" + head.text + "\" effects are not supported");
    }
    Literal l = literal_body(scope, false);
    if (l.equality) c_.fail(head, "\"=\" cannot be an effect");
    out.literals.push_back(std::move(l));
  }

  [[nodiscard]] const std::vector<Object>& objects() const {
    return problem_objects_ != nullptr ? *problem_objects_ : d_.constants;
  }

  Cursor& c_;
  Domain& d_;
  const std::vector<Object>* problem_objects_ = nullptr;
};

void problem_body(Cursor& c, const Domain& d, Problem& p) {
  Domain& dm = const_cast<Domain&>(d);  // DomainParser only reads the domain when parsing a problem
  DomainParser conditions(c, dm);
  conditions.use_problem_objects(&p.objects);
  p.objects = d.constants;
  c.open("to start the problem");
  c.word("define");
  c.open("before \"problem\"");
  c.word("problem");
  p.name = c.name("the problem's name").text;
  c.close("after the problem's name");
  bool have_goal = false;
  while (c.peek().kind == TokenKind::kOpen) {
    c.next();
    const Token& section = c.peek();
    if (section.kind != TokenKind::kKeyword) c.expected("a section such as :domain, :objects, :init or :goal");
    c.next();
    if (section.text == ":domain") {
      const Token& n = c.name("the domain's name");
      if (n.text != d.name) c.fail(n, "the problem is for domain " + n.text + ", the domain file defines " + d.name);
      c.close("after the domain's name");
    } else if (section.text == ":requirements") {
      while (c.peek().kind == TokenKind::kKeyword) c.next();
      c.close("after the requirements");
    } else if (section.text == ":objects") {
      for (const auto& tn : typed_list(c, TokenKind::kName, "an object's name", d.requirements)) {
        if (p.find_object(tn.name.text) >= 0) c.fail(tn.name, "object " + tn.name.text + " is declared twice");
        int type = 0;
        if (tn.type.kind != TokenKind::kEnd) {
          type = d.find_type(tn.type.text);
          if (type < 0) c.fail(tn.type, "unknown type " + tn.type.text);
        }
        p.objects.push_back({tn.name.text, type, c.at(tn.name)});
      }
      c.close("after the objects");
    } else if (section.text == ":init") {
      while (c.peek().kind == TokenKind::kOpen) {
        c.next();
        const Token& head = c.peek();
        if (head.kind == TokenKind::kName && (head.text == "not" || head.text == "=")) {
          c.fail(head, "the initial state lists true atoms only, found \"" + head.text + "\"");
        }
        Literal l;
        conditions.atom_body({}, l);
        Atom a{l.predicate, {}};
        for (const Term& t : l.args) a.args.push_back(t.index);
        p.init.push_back(std::move(a));
      }
      c.close("after the initial state");
    } else if (section.text == ":goal") {
      conditions.condition({}, p.goal, 0);
      c.close("after the goal");
      have_goal = true;
    } else if (section.text == ":metric") {
      c.fail(section, ":metric is not supported (every action costs 1)");
    } else {
      c.fail(section, "unknown problem section " + section.text);
    }
  }
  c.close("to end the problem");
  if (c.peek().kind != TokenKind::kEnd) c.expected("end of file after the problem");
  if (!have_goal) c.fail(c.peek(), "the problem has no :goal");
}

}  // namespace

Parsed<Domain> parse_domain(std::string_view text, const std::string& file) {
  try {
    Cursor c = make_cursor(text, file);
    Domain d;
    d.file = file;
    DomainParser(c, d).parse();
    return d;
  } catch (const ParseFailure& f) {
    return f.error;
  }
}

Parsed<Problem> parse_problem(std::string_view text, const std::string& file, const Domain& domain) {
  try {
    Cursor c = make_cursor(text, file);
    Problem p;
    p.file = file;
    problem_body(c, domain, p);
    return p;
  } catch (const ParseFailure& f) {
    return f.error;
  }
}

Parsed<std::string> read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{{path, 0, 0}, "cannot open the file"};
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) return Error{{path, 0, 0}, "cannot read the file"};
  return s.str();
}

}  // namespace ringlet::pddl
