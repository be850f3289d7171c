"""One machine in Promela: its variables, the abstraction of its action code, and its ringlet as a
Promela inline with the runtime's exact order (behaviour/src/llfsm/machine.cpp): the pending
control request (restart > suspend > resume), snapshot of the state's READ footprint, OnResume,
OnEntry, guards in declared order (first true fires: OnExit, change state) or Internal, write back
of the state's WRITE footprint.

What is kept: every variable that a guard, a property or an `assume` mentions, and everything
that statements writing such a variable read (a fixpoint: the cone of influence). Everything else
is dropped, with a note. A kept statement that cannot be translated is an error naming machine,
state, section, line and the reason, unless its target has a declared domain (`assume x in {..}`),
which makes every write of it a nondeterministic choice over the domain.
"""

from . import syntax as S
from .actions import split_statements
from .diagnostics import SourceError
from .expr_parser import parse_guard
from .promela_expr import DOUBLE_WORDS, ExprTranslator, Untranslatable, convert, literal
from .vexpr import InState, Temporal, parse_action_expr

REQ = {"resume": 1, "suspend": 2, "restart": 3}
INT_TYPES = {"size_t", "int8_t", "int16_t", "int32_t", "int64_t", "uint8_t", "uint16_t", "uint32_t", "uint64_t",
             "ptrdiff_t"}
PURE = ("std::clamp", "std::min", "std::max", "std::abs", "std::fabs")


def schema_ptype(type_text, schema):
    if type_text == "bool":
        return "bool"
    if type_text in DOUBLE_WORDS:
        return "fixed"
    if type_text in schema.enums or type_text.startswith("std::") and type_text[5:] in INT_TYPES:
        return "int"
    return None


def cxx_ptype(t):
    if t.kind == "fundamental":
        if t.words == ("bool",):
            return "bool"
        if any(w in DOUBLE_WORDS for w in t.words):
            return "fixed"
        return "int"
    if t.kind == "named" and len(t.parts) == 2 and t.parts[0] == "std" and t.parts[1] in INT_TYPES:
        return "int"
    return None


class MachineTx:
    def __init__(self, model, schema, index, period_ms, scheduled, diags):
        self.m, self.schema, self.diags = model, schema, diags
        self.M = model.name
        self.index = index
        self.period_ms = period_ms
        self.scheduled = scheduled  # names of the machines in the schedule
        self.state_index = {s.name: i for i, s in enumerate(model.states)}
        self.domains, self.values, self.calls = {}, {}, {}
        self.notes = []
        self.relevant = set()
        self.nd_count = 0
        self.thresholds = []
        self.timed_states = set()  # states with an after() guard
        self.read_domains()

    # -- declarations ------------------------------------------------------------------------
    def key_of(self, node):
        """("x", ext, field) / ("l", name) / ("p", name) for a variable reference, else None."""
        v = self.m.variables
        if isinstance(node, S.Member) and isinstance(node.obj, S.Name) and len(node.obj.parts) == 1:
            var = v.get(node.obj.parts[0])
            if var is not None and var.kind == "external":
                return ("x", var.name, node.field)
        if isinstance(node, S.Name) and len(node.parts) == 1 and node.parts[0] in v:
            var = v[node.parts[0]]
            return ({"local": "l", "parameter": "p"}.get(var.kind, "x"), var.name)
        return None

    def ptype(self, key):
        var = self.m.variables[key[1]]
        if key[0] == "x":
            fields = self.schema.messages.get(var.type, {})
            return schema_ptype(fields.get(key[2], ""), self.schema)
        return cxx_ptype(var.type.without_ref())

    def read_domains(self):
        for a in self.m.assumes:
            try:
                if a.kind == "call":
                    if not isinstance(a.target, S.Name) or len(a.target.parts) < 2:
                        raise SourceError(*a.target.pos, "expected 'assume call ns::function in {...}'")
                    self.calls["::".join(a.target.parts)] = [literal(x, "fixed", a.pos) for x in a.values.items]
                    continue
                key = self.key_of(a.target)
                if key is None:
                    raise SourceError(*a.target.pos, f"'{S.print_expr(a.target)}' is not a variable of {self.M} "
                                                     "(expected external.field, a local or a parameter)")
                ty = self.ptype(key)
                if ty is None:
                    raise SourceError(*a.target.pos, f"'{S.print_expr(a.target)}' is not a bool, integer, enum or double")
                if a.kind == "value":
                    if key[0] != "p":
                        raise SourceError(*a.pos, "'assume x = v' gives a parameter's value; a domain is 'assume x in {...}'")
                    self.values[key] = literal(a.values, ty, a.pos)
                else:
                    if key[0] == "p":
                        raise SourceError(*a.pos, "a parameter has one value: 'assume p = v'")
                    self.domains[key] = [self.literal_of(x, ty, key) for x in a.values.items]
            except Untranslatable as u:
                self.diags.error(*u.pos, u.why)
            except SourceError as e:
                self.diags.add(e)

    def literal_of(self, x, ty, key):
        if isinstance(x, S.Name) and len(x.parts) == 4 and x.parts[:2] == ("ringlet", "wb"):
            return self.schema.enums[x.parts[2]].index(x.parts[3])
        return literal(x, ty, x.pos)

    # -- relevance --------------------------------------------------------------------------
    def reads(self, tree, temps):
        """Keys an expression reads (temps expanded; arguments of declared calls not read)."""
        out, stack = set(), [tree]
        while stack:
            n = stack.pop()
            if isinstance(n, S.Call) and n.function in self.calls:
                continue
            if isinstance(n, S.Name) and len(n.parts) == 1 and n.parts[0] in temps:
                out |= temps[n.parts[0]][1]
                continue
            k = self.key_of(n)
            if k is not None:
                out.add(k)
                if isinstance(n, S.Member):
                    continue
            stack.extend(S.children(n) if not isinstance(n, (Temporal, InState)) else
                         (n.operands if isinstance(n, Temporal) else ()))
        return out

    def blocks(self):
        for s in self.m.states:
            for section, action in s.actions.items():
                try:
                    yield s, section, split_statements(action.tokens)
                except SourceError as e:
                    self.diags.error(e.line, e.col, f"machine {self.M}, state {s.name}, {section}: {e.message}")

    def target_key(self, stmt):
        name, field = stmt.target
        var = self.m.variables.get(name)
        if var is None:
            return None
        if field is None:
            return None if var.kind == "external" else ({"local": "l", "parameter": "p"}[var.kind], name)
        return ("x", name, field) if var.kind == "external" else None

    def expr_of(self, stmt):
        if stmt.rhs is None:
            return None
        try:
            return parse_action_expr(stmt.rhs, (stmt.line, 1))
        except SourceError:
            return None

    def compute_relevance(self, roots):
        rel = set(roots)
        for s in self.m.states:
            for t in s.transitions:
                rel |= self.reads(t.guard, {})
        rel |= set(self.domains)
        self.parsed = list(self.blocks())
        changed = True
        while changed:
            changed = False
            for s, section, stmts in self.parsed:
                changed |= self.relevance_pass(stmts, {}, rel)
        self.relevant = rel

    def relevance_pass(self, stmts, temps, rel):
        changed = False
        for st in stmts:
            if st.kind == "temp":
                e = self.expr_of(st)
                temps[st.target[0]] = (e, self.reads(e, temps) if e is not None else
                                       {k for k in self.token_keys(st.rhs or st.tokens)})
            elif st.kind in ("assign", "incr"):
                k = self.target_key(st)
                if k in rel and k not in self.domains:
                    e = self.expr_of(st)
                    new = self.reads(e, temps) if e is not None else set()
                    if not new <= rel:
                        rel |= new
                        changed = True
            elif st.kind == "if":
                sub = dict(temps)
                before = len(rel)
                changed |= self.relevance_pass(st.body, sub, rel) | self.relevance_pass(st.orelse, dict(temps), rel)
                if self.writes_relevant(st.body + st.orelse, rel) and \
                        not self.writes_only_declared_sets(st.body + st.orelse, rel):
                    try:
                        cond = parse_action_expr(st.cond, (st.line, 1))
                        new = self.reads(cond, temps)
                    except SourceError:
                        new = set()
                    if not new <= rel:
                        rel |= new
                        changed = True
                changed |= len(rel) != before
        return changed

    def writes_relevant(self, stmts, rel):
        for st in stmts:
            if st.kind in ("assign", "incr") and self.target_key(st) in rel:
                return True
            if st.kind == "request":
                return True
            if st.kind == "if" and self.writes_relevant(st.body + st.orelse, rel):
                return True
        return False

    def writes_only_declared_sets(self, stmts, rel):
        """True if every modelled write in stmts is to a variable with a declared set (and nothing
        requests): such an `if` is modelled as a choice of either branch, its condition unread
        (the writes are nondeterministic over the set anyway; whether one happens is the choice)."""
        for st in stmts:
            if st.kind in ("assign", "incr") and self.target_key(st) in rel and self.target_key(st) not in self.domains:
                return False
            if st.kind == "request":
                return False
            if st.kind == "if" and not self.writes_only_declared_sets(st.body + st.orelse, rel):
                return False
        return True

    def token_keys(self, tokens):
        out = set()
        for i, t in enumerate(tokens):
            if t.kind == "ident" and t.text in self.m.variables and not (i and tokens[i - 1].is_op(".", "::", "->")):
                var = self.m.variables[t.text]
                if var.kind == "external" and i + 2 < len(tokens) and tokens[i + 1].is_op("."):
                    out.add(("x", var.name, tokens[i + 2].text))
                elif var.kind != "external":
                    out.add(({"local": "l", "parameter": "p"}[var.kind], var.name))
        return out

    # -- names --------------------------------------------------------------------------------
    def var_name(self, key):
        if key[0] == "x":
            return f"{self.M}_x_{key[1]}_{key[2]}"
        return f"{self.M}_l_{key[1]}"

    def wb_name(self, key):
        return f"wb_{self.m.variables[key[1]].type}_{key[2]}"

    def modelled_fields(self, ext):
        return sorted(k for k in self.relevant if k[0] == "x" and k[1] == ext.name)

    def st(self, suffix):
        return f"{self.M}_{suffix}"

    # -- expressions --------------------------------------------------------------------------
    def translator(self, temps, pre, property_view=False, locate=None):
        def resolve(node):
            if isinstance(node, S.Name) and len(node.parts) == 1 and node.parts[0] in temps:
                e = temps[node.parts[0]][0]
                if e is None:
                    raise Untranslatable(node.pos, f"it uses '{node.parts[0]}', whose initialiser cannot be translated")
                return tr.value(e)
            k = self.key_of(node)
            if k is None:
                raise Untranslatable(node.pos, f"'{S.print_expr(node)}' is not a variable the model checker knows")
            ty = self.ptype(k)
            if ty is None:
                raise Untranslatable(node.pos, f"'{S.print_expr(node)}' is not a bool, integer, enum or double")
            if k[0] == "p":
                if k not in self.values:
                    raise Untranslatable(node.pos, f"parameter '{k[1]}' has no value: add 'assume {k[1]} = <value>'")
                return str(self.values[k]), ty
            if k not in self.relevant:
                raise Untranslatable(node.pos, f"'{S.print_expr(node)}' is not modelled")
            if k[0] == "x" and property_view:
                return self.wb_name(k), ty
            return self.var_name(k), ty

        def call(node):
            if node.function in self.calls:
                self.nd_count += 1
                nd = f"{self.M}_nd{self.nd_count}"
                pre.append((nd, self.calls[node.function]))
                return nd, "fixed"
            if node.function in ("after", "after_ms"):
                return self.after(node), "bool"
            if node.function in PURE:
                args = [tr.value(a) for a in node.args]
                ty = "fixed" if any(t == "fixed" for _, t in args) else "int"
                a = [convert(x, t, ty) for x, t in args]
                if node.function == "std::clamp" and len(a) == 3:
                    return f"({a[0]} < {a[1]} -> {a[1]} : ({a[0]} > {a[2]} -> {a[2]} : {a[0]}))", ty
                if node.function in ("std::min", "std::max") and len(a) == 2:
                    op = "<" if node.function == "std::min" else ">"
                    return f"({a[0]} {op} {a[1]} -> {a[0]} : {a[1]})", ty
                if node.function in ("std::abs", "std::fabs") and len(a) == 1:
                    return f"({a[0]} < 0 -> -({a[0]}) : {a[0]})", ty
            raise Untranslatable(node.pos, f"it calls '{node.function}', whose result the model does not declare "
                                           f"(add 'assume call {node.function} in {{...}}')")

        tr = ExprTranslator(resolve, call, self.schema.enums)
        return tr

    def after(self, node):
        ms = self.const_ms(node.args[0], node.function == "after_ms")
        turns = -(-ms // self.period_ms)
        self.thresholds.append(turns)
        return f"({self.st('t')} >= {turns})"

    def const_ms(self, e, plain_ms):
        if isinstance(e, S.NumberLit):
            if e.kind == "duration":
                factor = {"h": 3600000, "min": 60000, "s": 1000, "ms": 1}.get(e.suffix)
                if factor is None:
                    raise Untranslatable(e.pos, f"a duration in {e.suffix} (the clock counts turns of {self.period_ms} ms)")
                return int(e.text[:-len(e.suffix)].replace("'", "")) * factor
            if plain_ms and e.kind == "int":
                return int(e.text.replace("'", "").rstrip("uUlL"), 0)
        if isinstance(e, S.Name) and len(e.parts) == 1 and e.parts[0] in self.m.variables:
            var = self.m.variables[e.parts[0]]
            if var.kind == "parameter" and ("p", var.name) in self.values:
                return self.values[("p", var.name)]
            if var.kind == "local" and not self.is_written(var.name):
                return self.const_ms(var.init, plain_ms)
        raise Untranslatable(e.pos, "after()'s argument must be a literal, a parameter with a declared value "
                                    "or a local no action writes")

    def is_written(self, name):
        def walk(stmts):
            return any((st.kind in ("assign", "incr", "temp") and st.target[0] == name) or
                       (st.kind == "if" and walk(st.body + st.orelse)) for st in stmts)
        return any(walk(stmts) for _, _, stmts in self.parsed)

    # -- statements ---------------------------------------------------------------------------
    def havoc(self, name, values):
        return "if " + " ".join(f":: {name} = {v}" for v in values) + " fi"

    def with_pre(self, pre, line):
        out = [self.havoc(nd, vals) for nd, vals in pre]
        return out + [line]

    def stmts(self, state, section, stmts, temps):
        out = []
        for st in stmts:
            where = f"machine {self.M}, state {state.name}, {section}"
            try:
                out.extend(self.stmt(st, temps, where))
            except Untranslatable as u:
                self.diags.error(st.line, 1, f"{where}: cannot translate '{st.text}': {u.why}")
        return out

    def stmt(self, st, temps, where):
        if st.kind == "temp":
            temps[st.target[0]] = (self.expr_of(st), set())
            return []
        if st.kind in ("assign", "incr"):
            k = self.target_key(st)
            if k is None or k not in self.relevant:
                self.note(f"{where} line {st.line}: '{st.text}' dropped (writes nothing a property depends on)")
                return []
            name = self.var_name(k)
            if k in self.domains:
                self.note(f"{where} line {st.line}: '{st.text}' abstracted: any of {self.domains[k]}")
                return [self.havoc(name, self.domains[k])]
            if st.kind == "incr":
                e = S.NumberLit((st.line, 1), "1", "int")
            elif st.rhs is None:
                raise Untranslatable((st.line, 1), "its value is not an expression the model checker reads")
            else:
                e = self.expr_of(st)
            if e is None and st.kind != "incr":
                try:
                    parse_action_expr(st.rhs, (st.line, 1))
                except SourceError as err:
                    raise Untranslatable((st.line, 1), err.message)
            if st.op != "=":
                e = S.Binary((st.line, 1), st.op[0], S.Name((st.line, 1), (st.target[0],)) if st.target[1] is None
                             else S.Member((st.line, 1), S.Name((st.line, 1), (st.target[0],)), st.target[1]), e)
            pre = []
            text = self.translator(temps, pre).tx(e, self.ptype(k))
            return self.with_pre(pre, f"{name} = {text}")
        if st.kind == "request":
            if st.machine not in self.scheduled:
                self.note(f"{where} line {st.line}: '{st.text}' has no effect: no machine {st.machine} in this schedule")
                return []
            r = REQ[st.op]
            return [f"if :: {st.machine}_req < {r} -> {st.machine}_req = {r} :: else fi"]
        if st.kind == "if":
            body = self.stmts_inner(st.body, dict(temps), where)
            orelse = self.stmts_inner(st.orelse, dict(temps), where)
            if not body and not orelse:
                return []
            if self.writes_only_declared_sets(st.body + st.orelse, self.relevant):
                self.note(f"{where} line {st.line}: 'if ( {' '.join(t.text for t in st.cond)} )' abstracted: either "
                          "branch (it writes only variables with a declared set)")
                return ["if :: true -> " + "; ".join(body or ["skip"]) + " :: true -> " +
                        "; ".join(orelse or ["skip"]) + " fi"]
            try:
                cond = parse_action_expr(st.cond, (st.line, 1))
            except SourceError as err:
                raise Untranslatable((st.line, 1), err.message)
            pre = []
            c = self.translator(temps, pre).tx(cond, "bool")
            return self.with_pre(pre, f"if :: {c} -> " + "; ".join(body or ["skip"]) + " :: else -> " +
                                 "; ".join(orelse or ["skip"]) + " fi")
        # opaque
        named = self.token_keys(st.tokens) & self.relevant
        if named:
            raise Untranslatable((st.line, 1), "what it writes cannot be told, and it names " +
                                 ", ".join(sorted(".".join(k[1:]) for k in named)))
        self.note(f"{where} line {st.line}: '{st.text}' dropped (names nothing a property depends on)")
        return []

    def stmts_inner(self, stmts, temps, where):
        out = []
        for st in stmts:
            out.extend(self.stmt(st, temps, where))
        return out

    def note(self, text):
        if text not in self.notes:
            self.notes.append(text)

    # -- the ringlet --------------------------------------------------------------------------
    def guard(self, t, state):
        try:
            return self.translator({}, []).tx(t.guard, "bool")
        except Untranslatable as u:
            self.diags.error(t.line, 1, f"machine {self.M}, state {state.name}, transition to {t.target}: "
                                        f"cannot translate the guard: {u.why}")
            return "false"

    def section(self, s, name):
        blocks = {(st.name, sec): stmts for st, sec, stmts in self.parsed}
        stmts = blocks.get((s.name, name))
        return self.stmts(s, name, stmts, {}) if stmts else []

    def state_body(self, s):
        lines = []
        for ext in s.reads:
            for k in self.modelled_fields(ext):
                lines.append(f"{self.var_name(k)} = {self.wb_name(k)}")
        if "OnResume" in s.actions:
            lines.append(f"if :: {self.st('res')} -> " + "; ".join(self.section(s, "OnResume") or ["skip"]) + " :: else fi")
        entry = self.section(s, "OnEntry")
        lines.append(f"if :: {self.st('ent')} -> {self.st('ent')} = false; {self.st('t')} = 0" +
                     "".join("; " + x for x in entry) + " :: else fi")
        exit_ = self.section(s, "OnExit")
        internal = self.section(s, "Internal")
        chain = "; ".join(internal or ["skip"])
        before = len(self.thresholds)
        for t in reversed(s.transitions):
            fire = exit_ + [f"{self.st('st')} = {self.state_index[t.target]}", f"{self.st('ent')} = true"]
            chain = f"if :: {self.guard(t, s)} -> {'; '.join(fire)} :: else -> {chain} fi"
        lines.append(chain)
        if len(self.thresholds) > before:
            self.timed_states.add(self.state_index[s.name])
        for ext in s.writes:
            for k in self.modelled_fields(ext):
                lines.append(f"{self.wb_name(k)} = {self.var_name(k)}")
        return lines

    def reset_locals(self):
        out = []
        for k in sorted(self.relevant):
            if k[0] == "l":
                out.append(f"{self.var_name(k)} = {self.initial(k)}")
        return out

    def initial(self, k):
        var = self.m.variables[k[1]]
        try:
            return literal(var.init, self.ptype(k), var.pos)
        except (SourceError, Untranslatable):
            self.diags.error(*var.pos, f"machine {self.M}: the initial value of '{var.name}' is not a literal "
                                       "the model checker can hold")
            return 0

    def ringlet_inline(self):
        M = self.M
        bodies = []
        for i, s in enumerate(self.m.states):
            bodies.append(f"    :: {self.st('st')} == {i} ->\n       " + ";\n       ".join(self.state_body(s)))
        suspend_bodies = []
        for i, s in enumerate(self.m.states):
            if "OnSuspend" in s.actions:
                lines = [f"{self.var_name(k)} = {self.wb_name(k)}" for ext in s.reads for k in self.modelled_fields(ext)]
                lines += self.section(s, "OnSuspend")
                lines += [f"{self.wb_name(k)} = {self.var_name(k)}" for ext in s.writes for k in self.modelled_fields(ext)]
                suspend_bodies.append(f":: {self.st('st')} == {i} -> " + "; ".join(lines or ["skip"]))
        on_suspend = ("if " + " ".join(suspend_bodies) + " :: else fi; ") if suspend_bodies else ""
        restart = "; ".join(self.reset_locals() + [f"{self.st('st')} = {self.initial_state()}",
                                                   f"{self.st('ent')} = true", f"{self.st('susp')} = false"])
        return f"""inline ringlet_{M}() {{
  {self.st('res')} = false;
  {self.st('go')} = true;
  if
  :: {self.st('req')} == 3 -> {self.st('req')} = 0; {restart}
  :: {self.st('req')} == 2 -> {self.st('req')} = 0;
     if :: !{self.st('susp')} -> {on_suspend}{self.st('susp')} = true :: else fi;
     {self.st('go')} = false
  :: {self.st('req')} == 1 -> {self.st('req')} = 0;
     if :: {self.st('susp')} -> {self.st('susp')} = false; {self.st('res')} = true :: else fi
  :: else
  fi;
  if
  :: {self.st('go')} && !{self.st('susp')} ->
    if
{chr(10).join(bodies)}
    fi
  :: else
  fi
}}
"""

    def initial_state(self):
        return next(i for i, s in enumerate(self.m.states) if s.initial)

    def declarations(self):
        lines = [f"byte {self.st('st')} = {self.initial_state()};", f"bool {self.st('ent')} = true;",
                 f"bool {self.st('susp')} = false;", f"byte {self.st('req')} = 0;",
                 f"hidden byte {self.st('res')};", f"hidden byte {self.st('go')};",
                 f"byte {self.st('t')} = 0;"]
        for k in sorted(self.relevant):
            if k[0] == "l":
                lines.append(f"{self.pml_type(k)} {self.var_name(k)} = {self.initial(k)};")
            elif k[0] == "x" and self.m.variables[k[1]].access == "read":
                # A read-only copy is snapshotted before every use in a ringlet: dead between
                # ringlets, so kept out of the state vector (hidden; a bit cannot be hidden).
                lines.append(f"hidden {'byte' if self.pml_type(k) == 'bool' else self.pml_type(k)} {self.var_name(k)};")
            elif k[0] == "x":
                lines.append(f"{self.pml_type(k)} {self.var_name(k)} = 0;")
        for i in range(1, self.nd_count + 1):
            lines.append(f"hidden int {self.M}_nd{i};")
        return lines

    def pml_type(self, k):
        return {"bool": "bool", "int": "int", "fixed": "int"}[self.ptype(k)]

    def clock_reset(self):
        """After a ringlet: the clock only matters in a state with an after() guard that was not
        just entered (OnEntry resets it anyway), so elsewhere it is zeroed: fewer states, same
        behaviour."""
        if not self.thresholds:
            return ""
        timed = " || ".join(f"{self.st('st')} == {i}" for i in sorted(self.timed_states)) or "false"
        return f"if :: {self.st('ent')} || !({timed}) -> {self.st('t')} = 0 :: else fi;"

    def clock_cap(self):
        return max(self.thresholds, default=0)

    # -- properties in the machine's file -------------------------------------------------------
    def property_text(self, tree):
        def resolve_state(node):
            if node.machine and node.machine != self.M:
                raise Untranslatable(node.pos, f"at({node.machine}, ...) names another machine (in a machine's file: at(State))")
            if node.state not in self.state_index:
                raise Untranslatable(node.pos, f"unknown state '{node.state}' of {self.M}")
            return f"({self.st('st')} == {self.state_index[node.state]})"
        return property_text(tree, self.translator({}, [], property_view=True), resolve_state)


def property_text(tree, tr, resolve_state):
    """An ltl/assert tree in Promela's ltl syntax (atoms through `tr`)."""
    def walk(n):
        if isinstance(n, Temporal):
            if n.op in ("[]", "<>"):
                return f"{n.op} ({walk(n.operands[0])})"
            return f"(({walk(n.operands[0])}) {'->' if n.op == '->' else 'U'} ({walk(n.operands[1])}))"
        if isinstance(n, InState):
            return resolve_state(n)
        if isinstance(n, S.Paren):
            return f"({walk(n.expr)})"
        if isinstance(n, S.Unary) and n.op == "!":
            return f"!({walk(n.operand)})"
        if isinstance(n, S.Binary) and n.op in ("&&", "||") and _temporal(n):
            return f"({walk(n.left)} {n.op} {walk(n.right)})"
        if _temporal(n):
            raise Untranslatable(n.pos, "a temporal operator inside an arithmetic expression")
        return tr.tx(n, "bool")
    return walk(tree)


def _temporal(n):
    return any(isinstance(x, (Temporal, InState)) for x in S.walk(n)) if not isinstance(n, (Temporal, InState)) \
        else True


