#!/usr/bin/env python3
"""llfsmc: compiles one LLFSM model (a .machine file) to C++ and a Graphviz diagram.

    llfsmc.py MODEL [--hpp OUT.hpp --cpp OUT.cpp] [--dot OUT.dot]
              [--namespace ringlet::behaviour::machines] [--include-dir ringlet/behaviour/machines]

With no outputs it only checks the model. Errors go to stderr as `MODEL:LINE: message`, one per
line, and the exit status is 1; nothing is written then. The format is documented in
behaviour/README.md. Standard library only: it runs on the build host, also for cross builds.
"""

import argparse
import os
import re
import sys

ACTIONS = ("OnEntry", "OnExit", "Internal", "OnSuspend", "OnResume")
ACCESS = ("read", "write", "readwrite")
IDENT = r"[A-Za-z_][A-Za-z0-9_]*"
# Names the generated class or its Machine base already uses: a variable with one of these names
# would hide it inside action code.
RESERVED = {
    "after", "after_ms", "now", "name", "state_time", "ringlets", "suspended", "request",
    "suspend_machine", "resume_machine", "restart_machine", "current_state", "current_state_name",
    "state_count", "state_name", "wb_", "s",
}
# Guards may call only these.
GUARD_CALLS = {"after", "after_ms"}
# Identifiers a guard may use without declaring them.
GUARD_WORDS = {
    "true", "false", "nullptr", "and", "or", "not", "static_cast", "sizeof", "alignof",
    "int", "unsigned", "long", "short", "double", "float", "bool", "char", "std",
}
GUARD_FORBIDDEN_WORDS = {"new", "delete", "throw", "co_await", "co_yield", "const_cast", "reinterpret_cast"}
ASSIGNING_OPS = {"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>=", "++", "--"}
OPERATORS = sorted(
    ["->*", "<<=", ">>=", "...", "::", "->", "++", "--", "==", "!=", "<=", ">=", "&&", "||", "+=", "-=",
     "*=", "/=", "%=", "&=", "|=", "^=", "<<", ">>"], key=len, reverse=True)


class ModelError(Exception):
    pass


class Errors:
    def __init__(self, path):
        self.path = path
        self.items = []

    def add(self, line, message):
        self.items.append((line, message))

    def report(self):
        for line, message in sorted(self.items, key=lambda item: item[0]):
            sys.stderr.write(f"{self.path}:{line}: {message}\n")


class Var:
    def __init__(self, kind, name, ctype, line, access=None, init=None):
        self.kind, self.name, self.ctype, self.line = kind, name, ctype, line
        self.access, self.init = access, init

    @property
    def member(self):
        return {"external": "x_", "local": "l_", "parameter": "p_"}[self.kind] + self.name + "_"

    @property
    def value_type(self):
        """The C++ type the action code sees (a reference parameter's referred-to type)."""
        if self.kind == "external":
            return wb_type(self.ctype)
        return self.ctype[:-1].rstrip() if self.ctype.endswith("&") else self.ctype


class Transition:
    def __init__(self, target, guard, line):
        self.target, self.guard, self.line = target, guard, line


class State:
    def __init__(self, name, line, initial):
        self.name, self.line, self.initial = name, line, initial
        self.actions = {}  # section -> (first code line, code)
        self.transitions = []
        self.submachine = None  # (machine, mode, line)
        self.reads, self.writes = [], []


class Model:
    def __init__(self):
        self.name = None
        self.name_line = 0
        self.includes = []
        self.variables = {}  # name -> Var, declaration order kept
        self.states = []


# --- C++ token scanning (enough to find identifiers, braces and operators outside literals) -------

def tokens(code):
    """Yields (kind, text) with kind in ident, number, string, op; comments dropped."""
    i, n = 0, len(code)
    while i < n:
        c = code[i]
        if c.isspace():
            i += 1
        elif code.startswith("//", i):
            j = code.find("\n", i)
            i = n if j < 0 else j
        elif code.startswith("/*", i):
            j = code.find("*/", i + 2)
            i = n if j < 0 else j + 2
        elif c in "\"'":
            j = i + 1
            while j < n and code[j] != c:
                j += 2 if code[j] == "\\" else 1
            yield "string", code[i:j + 1]
            i = j + 1
        elif c.isdigit() or (c == "." and i + 1 < n and code[i + 1].isdigit()):
            m = re.match(r"[0-9.]([0-9A-Za-z_.']|[eEpP][+-])*", code[i:])
            yield "number", m.group(0)
            i += len(m.group(0))
        elif c.isalpha() or c == "_":
            m = re.match(IDENT, code[i:])
            yield "ident", m.group(0)
            i += len(m.group(0))
        else:
            for op in OPERATORS:
                if code.startswith(op, i):
                    yield "op", op
                    i += len(op)
                    break
            else:
                yield "op", c
                i += 1


def free_identifiers(code):
    """Identifiers not reached through `.`, `->` or `::` (so member names do not count)."""
    toks = list(tokens(code))
    out = []
    for k, (kind, text) in enumerate(toks):
        if kind != "ident":
            continue
        if k > 0 and toks[k - 1] == ("op", ".") or k > 0 and toks[k - 1][1] in ("->", "::"):
            continue
        out.append((text, toks[k + 1] if k + 1 < len(toks) else None))
    return out


def block_end(text, start):
    """Index just past the `}` that closes the `{` before `start`, or -1."""
    depth, i, n = 1, start, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        if text.startswith("/*", i):
            j = text.find("*/", i + 2)
            if j < 0:
                return -1
            i = j + 2
            continue
        if c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            i = j + 1
            continue
        if c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
            if depth == 0:
                return i + 1
        i += 1
    return -1


# --- parsing ------------------------------------------------------------------------------------

# Variable declarations: keyword -> (kind, pattern with groups name, type[, access|init], what to
# say when a line does not match).
DECLARATIONS = {
    "external": ("external", r"external\s+(" + IDENT + r")\s*:\s*(" + IDENT + r"(?:::" + IDENT + r")*)\s+(\S+)",
                 "'external <name> : <WhiteboardType> read|write|readwrite'"),
    "local": ("local", r"local\s+(" + IDENT + r")\s*:\s*([^=]+?)\s*=\s*(.+)",
              "'local <name> : <C++ type> = <initial value>'"),
    "parameter": ("parameter", r"parameter\s+(" + IDENT + r")\s*:\s*([^=]+?)",
                  "'parameter <name> : <C++ type>' (no initial value: it is bound at construction)"),
}


def parse(text, errors):
    model = Model()
    lines = text.split("\n")
    offsets = [0]
    for line in lines:
        offsets.append(offsets[-1] + len(line) + 1)
    state = None
    k = 0
    while k < len(lines):
        lineno = k + 1
        raw = lines[k]
        line = raw.strip()
        k += 1
        if not line or line.startswith("#"):
            continue
        word = line.split()[0]
        if model.name is None and word != "machine":
            errors.add(lineno, "expected 'machine <Name>' before anything else")
            raise ModelError()
        if word == "machine":
            m = re.fullmatch(r"machine\s+(" + IDENT + r")", line)
            if not m:
                errors.add(lineno, "expected 'machine <Name>'")
            elif model.name is not None:
                errors.add(lineno, "a model describes one machine: second 'machine' line")
            else:
                model.name, model.name_line = m.group(1), lineno
        elif word == "include":
            m = re.fullmatch(r"include\s+(<[^<>\s]+>|\"[^\"\s]+\")", line)
            if not m or state is not None:
                errors.add(lineno, "expected 'include <header>' or 'include \"header\"' outside states")
            else:
                model.includes.append(m.group(1))
        elif word in DECLARATIONS:
            kind, pattern, usage = DECLARATIONS[word]
            if state is not None:
                errors.add(lineno, f"{kind} variables are declared outside states")
                continue
            m = re.fullmatch(pattern, line)
            if not m:
                errors.add(lineno, f"expected {usage}")
                continue
            name, ctype, extra = m.group(1), m.group(2), m.group(3) if m.lastindex >= 3 else None
            if kind == "external" and extra not in ACCESS:
                errors.add(lineno, f"unknown access mode '{extra}' for external '{name}' (expected read, write or readwrite)")
                continue
            declare(model, Var(kind, name, ctype, lineno,
                               access=extra if kind == "external" else None,
                               init=extra if kind == "local" else None), errors)
        elif word == "state":
            m = re.fullmatch(r"state\s+(" + IDENT + r")(\s+initial)?", line)
            if state is not None:
                errors.add(lineno, f"state '{state.name}' (line {state.line}) is not closed with 'end'")
            if not m:
                errors.add(lineno, "expected 'state <Name>' or 'state <Name> initial'")
                state = State("?", lineno, False)
                continue
            state = State(m.group(1), lineno, m.group(2) is not None)
            for other in model.states:
                if other.name == state.name:
                    errors.add(lineno, f"duplicate state '{state.name}' (first declared on line {other.line})")
            model.states.append(state)
        elif word == "end":
            if state is None:
                errors.add(lineno, "'end' outside a state")
            state = None
        elif line.startswith("->"):
            if state is None:
                errors.add(lineno, "transition outside a state")
                continue
            m = re.fullmatch(r"->\s*(" + IDENT + r")\s+when\s+(.+)", line)
            if not m:
                errors.add(lineno, "expected '-> <Target> when <expression>'")
                continue
            state.transitions.append(Transition(m.group(1), m.group(2).strip(), lineno))
        elif word == "submachine":
            m = re.fullmatch(r"submachine\s+(" + IDENT + r")(?:\s+(\S+))?", line)
            if state is None:
                errors.add(lineno, "a submachine belongs to a state")
            elif not m:
                errors.add(lineno, "expected 'submachine <Machine> [restart|resume]'")
            elif m.group(2) not in (None, "restart", "resume"):
                errors.add(lineno, f"unknown submachine entry mode '{m.group(2)}' (expected restart or resume)")
            elif state.submachine is not None:
                errors.add(lineno, f"state '{state.name}' already owns submachine '{state.submachine[0]}'")
            else:
                state.submachine = (m.group(1), m.group(2) or "restart", lineno)
        elif word.rstrip("{") in ACTIONS or re.match(r"(" + IDENT + r")\s*\{", line):
            section = re.match(IDENT, line).group(0)
            if section not in ACTIONS:
                errors.add(lineno, f"unknown section '{section}' (expected one of {', '.join(ACTIONS)})")
            if state is None:
                errors.add(lineno, f"'{section}' outside a state")
            brace = raw.find("{")
            if brace < 0 or raw[raw.find(section) + len(section):brace].strip():
                errors.add(lineno, f"expected '{section} {{' on one line")
                raise ModelError()
            start = offsets[k - 1] + brace + 1
            end = block_end(text, start)
            if end < 0:
                errors.add(lineno, f"'{section}' block is not closed")
                raise ModelError()
            end_line = text.count("\n", 0, end - 1)  # 0-based line of the closing brace
            rest = text[end:offsets[end_line + 1] - 1 if end_line + 1 < len(offsets) else len(text)].strip()
            if rest and not rest.startswith("//") and not rest.startswith("#"):
                errors.add(end_line + 1, "nothing may follow the '}' closing a code block")
            k = end_line + 1
            if state is not None and section in ACTIONS:
                if section in state.actions:
                    errors.add(lineno, f"state '{state.name}' has two '{section}' sections")
                first_line = lineno if text[start:offsets[lineno]].strip() else lineno + 1
                code = text[start:end - 1]
                if not text[start:offsets[lineno]].strip():
                    code = code.split("\n", 1)[1] if "\n" in code else ""
                state.actions[section] = (first_line, code)
        else:
            errors.add(lineno, f"unknown keyword '{word}'")
    if state is not None:
        errors.add(state.line, f"state '{state.name}' is not closed with 'end'")
    if model.name is None:
        errors.add(1, "missing 'machine <Name>'")
        raise ModelError()
    return model


def declare(model, var, errors):
    if var.name in RESERVED:
        errors.add(var.line, f"variable name '{var.name}' is reserved by the runtime")
    elif var.name in model.variables:
        errors.add(var.line, f"duplicate variable '{var.name}' (first declared on line {model.variables[var.name].line})")
    else:
        model.variables[var.name] = var


# --- checks -------------------------------------------------------------------------------------

def check(model, errors):
    names = {s.name for s in model.states}
    initials = [s for s in model.states if s.initial]
    if not model.states:
        errors.add(model.name_line, f"machine '{model.name}' has no states")
    elif not initials:
        errors.add(model.name_line, f"machine '{model.name}' has no initial state (mark one 'state <Name> initial')")
    for extra in initials[1:]:
        errors.add(extra.line, f"second initial state '{extra.name}' (first is '{initials[0].name}')")
    for s in model.states:
        if s.submachine and s.submachine[0] == model.name:
            errors.add(s.submachine[2], f"machine '{model.name}' cannot be its own submachine")
        for t in s.transitions:
            if t.target not in names:
                errors.add(t.line, f"unknown state '{t.target}' in transition from '{s.name}'")
            check_guard(model, t, errors)


def check_guard(model, t, errors):
    toks = list(tokens(t.guard))
    depth = 0
    for k, (kind, text) in enumerate(toks):
        nxt = toks[k + 1] if k + 1 < len(toks) else None
        prev = toks[k - 1] if k > 0 else None
        if kind == "op":
            if text in ASSIGNING_OPS:
                errors.add(t.line, f"guard has side effects: '{text}' in '{t.guard}'")
                return
            depth += text == "("
            depth -= text == ")"
            continue
        if kind != "ident":
            continue
        if text in GUARD_FORBIDDEN_WORDS:
            errors.add(t.line, f"guard has side effects: '{text}' in '{t.guard}'")
            return
        member = prev is not None and prev[1] in (".", "->", "::")
        if nxt == ("op", "(") and text not in GUARD_CALLS and text not in ("sizeof", "alignof"):
            errors.add(t.line, f"guard calls '{text}()': only after() and after_ms() may be called in a guard")
            return
        if member or (nxt is not None and nxt[1] == "::"):
            continue
        if text in GUARD_CALLS or text in GUARD_WORDS:
            continue
        if text not in model.variables:
            errors.add(t.line, f"undeclared variable '{text}' in guard '{t.guard}'")
            return
    if depth != 0:
        errors.add(t.line, f"unbalanced parentheses in guard '{t.guard}'")


def footprints(model):
    """READ/WRITE footprint of every state: the externals its code and guards mention."""
    for s in model.states:
        code = " ".join([c for _, c in s.actions.values()] + [t.guard for t in s.transitions])
        used = {name for name, _ in free_identifiers(code)}
        for v in model.variables.values():
            if v.kind == "external" and v.name in used:
                if v.access in ("read", "readwrite"):
                    s.reads.append(v)
                if v.access in ("write", "readwrite"):
                    s.writes.append(v)


def union(model, attr):
    seen = []
    for s in model.states:
        for v in getattr(s, attr):
            if v.ctype not in [x.ctype for x in seen]:
                seen.append(v)
    return seen


# --- C++ ----------------------------------------------------------------------------------------

def wb_type(ctype):
    return ctype if "::" in ctype else "::ringlet::wb::" + ctype


def cxx_string(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


class Emitter:
    """Collects output lines and knows its own line numbers (for #line back into the output)."""

    def __init__(self, out_name):
        self.lines = []
        self.out_name = out_name

    def __call__(self, text=""):
        self.lines.extend(text.split("\n"))

    def model_code(self, model_path, first_line, code, indent="    "):
        self.lines.append(f"#line {first_line} {cxx_string(model_path)}")
        body = code.rstrip("\n").split("\n") if code.strip() else []
        self.lines.extend(body)
        self.lines.append(f"#line {len(self.lines) + 2} {cxx_string(self.out_name)}")

    def text(self):
        return "\n".join(self.lines) + "\n"


def refs(model, code, const_all):
    """Reference declarations for the variables `code` mentions, in declaration order."""
    used = {name for name, _ in free_identifiers(code)}
    out = []
    for v in model.variables.values():
        if v.name not in used:
            continue
        const = const_all or (v.kind == "external" and v.access == "read")
        out.append(f"  [[maybe_unused]] {'const ' if const else ''}{v.value_type}& {v.name} = {v.member};")
    return out


def generate_header(model, ns, include_path):
    cls = model.name
    reqs, provs = union(model, "reads"), union(model, "writes")
    e = Emitter(include_path)
    e(f"// Generated by llfsmc from {model.source_name}: do not edit, edit the model.")
    e("#pragma once")
    for inc in ["<array>", "<chrono>", "<cstddef>", "<span>", "<string_view>"]:
        e(f"#include {inc}")
    e()
    e('#include "ringlet/behaviour/llfsm/machine.hpp"')
    e('#include "ringlet/whiteboard/whiteboard.hpp"')
    for inc in model.includes:
        e(f"#include {inc}")
    e()
    e(f"namespace {ns} {{")
    e()
    e(f"class {cls} final : public ::ringlet::behaviour::llfsm::Machine {{")
    e(" public:")
    e("  using StateIndex = ::ringlet::behaviour::llfsm::StateIndex;")
    e(f"  static constexpr std::string_view kName{{{cxx_string(cls)}}};")
    for i, s in enumerate(model.states):
        e(f"  static constexpr StateIndex kState{s.name} = {i};")
    e(f"  static constexpr std::array<std::string_view, {len(model.states)}> kStates{{"
      + ", ".join(cxx_string(s.name) for s in model.states) + "};")
    e("  /// REQUIRES: union of the states' READ footprints (whiteboard type names).")
    e(f"  static constexpr std::array<std::string_view, {len(reqs)}> kRequires{{"
      + ", ".join(f"{wb_type(v.ctype)}::kName" for v in reqs) + "};")
    e("  /// PROVIDES: union of the states' WRITE footprints.")
    e(f"  static constexpr std::array<std::string_view, {len(provs)}> kProvides{{"
      + ", ".join(f"{wb_type(v.ctype)}::kName" for v in provs) + "};")
    e()
    e(f"  explicit {cls}({constructor_params(model)}) noexcept;")
    e()
    e("  [[nodiscard]] std::size_t state_count() const noexcept override { return kStates.size(); }")
    e("  [[nodiscard]] std::string_view state_name(StateIndex s) const noexcept override {")
    e('    return s < kStates.size() ? kStates[s] : std::string_view{"?"};')
    e("  }")
    e("  [[nodiscard]] std::span<const std::string_view> requires_types() const noexcept override { return kRequires; }")
    e("  [[nodiscard]] std::span<const std::string_view> provides_types() const noexcept override { return kProvides; }")
    if any(s.submachine for s in model.states):
        e("  [[nodiscard]] ::ringlet::behaviour::llfsm::SubmachineLink submachine(StateIndex s) const noexcept override;")
    e()
    e("  // Read-only views of the variables (tests, tools).")
    for v in model.variables.values():
        e(f"  [[nodiscard]] const {v.value_type}& {v.kind}_{v.name}() const noexcept {{ return {v.member}; }}")
    e()
    e(" protected:")
    e("  void snapshot(StateIndex s) noexcept override;")
    for section, hook in HOOKS:
        if any(section in s.actions for s in model.states):
            e(f"  void {hook}(StateIndex s) override;")
    e("  [[nodiscard]] StateIndex fire(StateIndex s) noexcept override;")
    e("  void write_back(StateIndex s) noexcept override;")
    e("  void reset_locals() noexcept override;")
    e()
    e(" private:")
    for s in model.states:
        for section in ACTIONS:
            if section in s.actions:
                e(f"  void {s.name}_{section}();")
    e()
    # maybe_unused: a machine that reads and writes no message never touches it (clang warns).
    e("  [[maybe_unused]] ::ringlet::wb::Whiteboard& wb_;")
    for v in model.variables.values():
        if v.kind == "external":
            e(f"  {wb_type(v.ctype)} {v.member}{{}};  // {v.access}")
        elif v.kind == "parameter":
            e(f"  {v.ctype} {v.member};  // parameter: bound at construction, kept by restart")
        else:
            e(f"  {v.ctype} {v.member} = {v.init};")
    e("};")
    e()
    e(f"}}  // namespace {ns}")
    return e.text()


def emit_state_switch(e, signature, cases):
    """A member function that runs, for the current state, that state's statements (cases: a list
    of (state name, statements)); other states do nothing."""
    e(f"{signature} {{")
    e("  switch (s) {")
    for name, statements in cases:
        e(f"    case kState{name}:")
        for statement in statements:
            e("      " + statement)
        e("      break;")
    e("    default:")
    e("      break;")
    e("  }")
    e("}")
    e()


def constructor_params(model):
    """The whiteboard, then every parameter in declaration order."""
    return ", ".join(["::ringlet::wb::Whiteboard& wb"] + [
        f"{v.ctype} {v.name}" for v in model.variables.values() if v.kind == "parameter"])


HOOKS = [("OnEntry", "on_entry"), ("OnExit", "on_exit"), ("Internal", "internal"),
         ("OnSuspend", "on_suspend"), ("OnResume", "on_resume")]


def generate_source(model, ns, include_path, model_path, out_name):
    cls = model.name
    e = Emitter(out_name)
    e(f"// Generated by llfsmc from {model.source_name}: do not edit, edit the model.")
    e(f'#include "{include_path}"')
    e()
    e(f"namespace {ns} {{")
    e()
    e("using namespace std::chrono_literals;")
    e("using ::ringlet::behaviour::llfsm::kNoState;")
    e()
    e(f"{cls}::{cls}({constructor_params(model)}) noexcept")
    initial = next((i for i, s in enumerate(model.states) if s.initial), 0)
    bound = "".join(f", {v.member}({v.name})" for v in model.variables.values() if v.kind == "parameter")
    e(f"    : ::ringlet::behaviour::llfsm::Machine(kName, {initial}), wb_(wb){bound} {{}}")
    e()
    if any(s.submachine for s in model.states):
        e(f"::ringlet::behaviour::llfsm::SubmachineLink {cls}::submachine(StateIndex s) const noexcept {{")
        e("  switch (s) {")
        for s in model.states:
            if s.submachine:
                mode = "kRestart" if s.submachine[1] == "restart" else "kResume"
                e(f"    case kState{s.name}:")
                e(f"      return {{{cxx_string(s.submachine[0])}, ::ringlet::behaviour::llfsm::SubmachineEntry::{mode}}};")
        e("    default:")
        e("      return {};")
        e("  }")
        e("}")
        e()
    # READ footprint in, WRITE footprint out.
    for hook, attr, stmt in [("snapshot", "reads", "{m} = wb_.get<{t}>();"),
                             ("write_back", "writes", "wb_.post<{t}>({m});")]:
        emit_state_switch(e, f"void {cls}::{hook}(StateIndex s) noexcept",
                          [(st.name, [stmt.format(m=v.member, t=wb_type(v.ctype)) for v in getattr(st, attr)])
                           for st in model.states if getattr(st, attr)])
    for section, hook in HOOKS:
        if not any(section in s.actions for s in model.states):
            continue
        emit_state_switch(e, f"void {cls}::{hook}(StateIndex s)",
                          [(st.name, [f"{st.name}_{section}();"]) for st in model.states if section in st.actions])
    e(f"auto {cls}::fire(StateIndex s) noexcept -> StateIndex {{")
    e("  switch (s) {")
    for s in model.states:
        if not s.transitions:
            continue
        e(f"    case kState{s.name}: {{")
        for r in refs(model, " ".join(t.guard for t in s.transitions), True):
            e("  " * 2 + r)
        for t in s.transitions:
            e("      if (")
            e.model_code(model_path, t.line, t.guard)
            e(f"      ) return kState{t.target};")
        e("      return kNoState;")
        e("    }")
    e("    default:")
    e("      return kNoState;")
    e("  }")
    e("}")
    e()
    e(f"void {cls}::reset_locals() noexcept {{")
    for v in model.variables.values():
        if v.kind == "local":
            e(f"  {{ {v.ctype} fresh = {v.init}; {v.member} = fresh; }}")
    e("}")
    for s in model.states:
        for section in ACTIONS:
            if section not in s.actions:
                continue
            first, code = s.actions[section]
            e()
            e(f"void {cls}::{s.name}_{section}() {{")
            for r in refs(model, code, False):
                e(r)
            e.model_code(model_path, first, code)
            e("}")
    e()
    e(f"}}  // namespace {ns}")
    return e.text()


# --- Graphviz -----------------------------------------------------------------------------------

def dot_string(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def generate_dot(model):
    out = [f"// Generated by llfsmc from {model.source_name}: states, initial state, ordered guards.",
           f"digraph {model.name} {{",
           f"  label={dot_string(model.name)}; labelloc=t; fontname=\"Helvetica\";",
           "  rankdir=LR;",
           "  node [shape=box, style=rounded, fontname=\"Helvetica\", fontsize=11];",
           "  edge [fontname=\"Helvetica\", fontsize=10];",
           "  __initial [shape=point, width=0.15, label=\"\"];"]
    for s in model.states:
        label = s.name
        if s.reads:
            label += "\\nREAD " + ", ".join(v.ctype for v in s.reads)
        if s.writes:
            label += "\\nWRITE " + ", ".join(v.ctype for v in s.writes)
        if s.submachine:
            label += f"\\nsubmachine {s.submachine[0]} ({s.submachine[1]})"
        attrs = f"label=\"{label.replace(chr(34), chr(92) + chr(34))}\""
        if s.initial:
            attrs += ", penwidth=2"
        out.append(f"  {s.name} [{attrs}];")
    initial = next((s for s in model.states if s.initial), None)
    if initial:
        out.append(f"  __initial -> {initial.name};")
    for s in model.states:
        for i, t in enumerate(s.transitions, 1):
            out.append(f"  {s.name} -> {t.target} [label={dot_string(f'{i}: {t.guard}')}];")
    out.append("}")
    return "\n".join(out) + "\n"


# --- main ---------------------------------------------------------------------------------------

def write_output(path, text):
    """Always (re)writes: the build system compares the output's time with the model's."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("model")
    ap.add_argument("--hpp")
    ap.add_argument("--cpp")
    ap.add_argument("--dot")
    ap.add_argument("--namespace", default="ringlet::behaviour::machines")
    ap.add_argument("--include-dir", default="ringlet/behaviour/machines",
                    help="directory the generated header is included from (include path prefix)")
    args = ap.parse_args(argv)

    errors = Errors(args.model)
    try:
        with open(args.model, encoding="utf-8") as f:
            text = f.read()
    except OSError as exc:
        sys.stderr.write(f"{args.model}:1: cannot read: {exc.strerror}\n")
        return 1
    try:
        model = parse(text, errors)
        check(model, errors)
    except ModelError:
        pass
    if errors.items:
        errors.report()
        return 1
    model.source_name = os.path.basename(args.model)
    footprints(model)
    stem = os.path.splitext(os.path.basename(args.model))[0]
    include_path = f"{args.include_dir}/{stem}.hpp"
    model_path = os.path.abspath(args.model)
    if args.hpp:
        write_output(args.hpp, generate_header(model, args.namespace, include_path))
    if args.cpp:
        write_output(args.cpp, generate_source(model, args.namespace, include_path, model_path,
                                                   os.path.abspath(args.cpp)))
    if args.dot:
        write_output(args.dot, generate_dot(model))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
