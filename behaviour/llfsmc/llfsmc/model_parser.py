"""The .machine format: one declaration per line, C++ code blocks between braces
(behaviour/README.md). Lines are tokenized (lexer.lex_line) and parsed by their first word;
guards, types and initial values go to expr_parser; code blocks are scanned by lexer.scan_block.
Errors are collected (one per line at most) so that a model shows all its mistakes at once,
except where the structure is lost (an unclosed code block), which stops the parse."""

from .diagnostics import Abort, SourceError
from .expr_parser import parse_guard, parse_initial_value, parse_type
from .lexer import LineMap, lex_line, scan_block
from .model import ACCESS, ACTIONS, Action, Assume, Model, Property, State, Transition, Var
from .vexpr import parse_ltl
from .names import MAX_NAME_LENGTH, RUNTIME_RESERVED, identifier_problem

USAGE = {
    "machine": "expected 'machine <Name>'",
    "external": "expected 'external <name> : <WhiteboardType> read|write|readwrite'",
    "local": "expected 'local <name> : <C++ type> = <initial value>'",
    "parameter": "expected 'parameter <name> : <C++ type>' (no initial value: it is bound at construction)",
    "state": "expected 'state <Name>' or 'state <Name> initial'",
    "transition": "expected '-> <Target> when <expression>'",
    "submachine": "expected 'submachine <Machine> [restart|resume]'",
    "end": "expected 'end' alone on its line",
    "assume": "expected 'assume <input>.<field> in {v, ...}', 'assume <local> in {v, ...}', "
              "'assume <parameter> = <value>' or 'assume call <ns::function> in {v, ...}'",
    "ltl": "expected 'ltl <name>: <formula>'",
    "assert": "expected 'assert <name>: <expression>'",
}
HEADER_CHARS = set("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_./+-")


def _end_of(tokens, line, raw):
    """Position just past the last token (where 'ends early' errors point)."""
    if tokens:
        last = tokens[-1]
        return last.line, last.col + len(last.text)
    return line, len(raw.rstrip()) + 1


def check_name(tok, what, diags, reserved=False, length=False):
    """A name must be a C++ identifier that is not a keyword (and, for variables, not one the
    runtime uses; for machines and states, short enough for FsmStatus). True if it is fine."""
    problem = identifier_problem(tok.text)
    if problem is None and reserved and tok.text in RUNTIME_RESERVED:
        problem = f"'{tok.text}' is reserved by the runtime"
    if problem is None and length and len(tok.text) > MAX_NAME_LENGTH:
        problem = f"'{tok.text}' is longer than {MAX_NAME_LENGTH} characters (FsmStatus carries it in FixedString<{MAX_NAME_LENGTH}>)"
    if problem:
        diags.error(tok.line, tok.col, f"{problem}: it cannot name a {what}")
        return False
    return True


def _section_header(raw):
    """(word, col of word, index of '{') when the line is `<Word> {...`, else None."""
    i = len(raw) - len(raw.lstrip())
    j = i
    while j < len(raw) and raw[j].isascii() and (raw[j].isalnum() or raw[j] == "_"):
        j += 1
    word = raw[i:j]
    if not word or word[0].isdigit():
        return None
    b = j
    while b < len(raw) and raw[b] in " \t":
        b += 1
    if b < len(raw) and raw[b] == "{":
        return word, i + 1, b
    if word in ACTIONS:
        return word, i + 1, -1
    return None


class ModelParser:
    def __init__(self, text, diags):
        self.text = text
        self.diags = diags
        self.lines = text.split("\n")
        self.offsets = [0]
        for line in self.lines:
            self.offsets.append(self.offsets[-1] + len(line) + 1)
        self.pos = LineMap(text)
        self.model = Model()
        self.state = None

    def parse(self):
        k = 0
        while k < len(self.lines):
            k = self.line(k)
        if self.state is not None:
            self.diags.error(*self.state.pos, f"state '{self.state.name}' is not closed with 'end'")
        if self.model.name is None:
            self.diags.error(1, 1, "missing 'machine <Name>'")
            raise Abort()
        return self.model

    def line(self, k):
        """Parses line k (0-based); returns the index of the next line to parse."""
        lineno, raw = k + 1, self.lines[k]
        header = _section_header(raw)
        if header is not None and self.model.name is not None:
            return self.code_block(k, *header)
        stripped = raw.lstrip()
        if stripped.startswith("include") and stripped[7:8] in (" ", "\t") and self.model.name is not None:
            self.include(lineno, raw)
            return k + 1
        try:
            toks = lex_line(raw, lineno)
        except SourceError as e:
            self.diags.add(e)
            if self.model.name is None:
                raise Abort()
            return k + 1
        if not toks:
            return k + 1
        first = toks[0]
        if self.model.name is None and not first.is_word("machine"):
            self.diags.error(first.line, first.col, "expected 'machine <Name>' before anything else")
            raise Abort()
        try:
            if first.is_op("->"):
                self.transition(toks, raw)
            elif first.kind == "ident" and hasattr(self, "kw_" + first.text):
                getattr(self, "kw_" + first.text)(toks, raw)
            else:
                self.diags.error(first.line, first.col, f"unknown keyword '{first.text}'")
        except SourceError as e:
            self.diags.add(e)
        return k + 1

    def usage(self, tok, key):
        raise SourceError(tok.line, tok.col, USAGE[key])

    # -- declarations --
    def kw_machine(self, toks, raw):
        first = toks[0]
        if len(toks) != 2 or toks[1].kind != "ident":
            self.usage(first, "machine")
        if self.model.name is not None:
            raise SourceError(first.line, first.col, "a model describes one machine: second 'machine' line")
        if check_name(toks[1], "machine", self.diags, length=True):
            self.model.name, self.model.name_pos = toks[1].text, (first.line, first.col)
        else:
            raise Abort()

    def include(self, lineno, raw):
        col = len(raw) - len(raw.lstrip()) + 1
        if self.state is not None:
            self.diags.error(lineno, col, "'include' lines belong outside states")
            return
        rest = raw.lstrip()[len("include"):]
        start = len(raw) - len(rest)
        body = rest.lstrip()
        at = len(raw) - len(body) + 1
        close = {"<": ">", '"': '"'}.get(body[:1])
        end = body.find(close, 1) if close else -1
        name = body[1:end] if end > 0 else ""
        tail = body[end + 1:].strip() if end > 0 else ""
        if not name or not set(name) <= HEADER_CHARS or ".." in name or (tail and not tail.startswith("#")):
            self.diags.error(lineno, at if start < len(raw) else col,
                             "expected 'include <header>' or 'include \"header\"' "
                             "(letters, digits and _ . / + - in the header name)")
            return
        self.model.includes.append(body[:end + 1])

    def declaration_head(self, toks, key):
        """`<kw> <name> : ...` -> (name token, tokens after the colon)."""
        if len(toks) < 4 or toks[1].kind != "ident" or not toks[2].is_op(":"):
            self.usage(toks[0], key)
        if self.state is not None:
            raise SourceError(toks[0].line, toks[0].col, f"{key} variables are declared outside states")
        return toks[1], toks[3:]

    def kw_external(self, toks, raw):
        name, rest = self.declaration_head(toks, "external")
        if len(rest) != 2 or rest[0].kind != "ident" or rest[1].kind != "ident":
            self.usage(toks[0], "external")
        if rest[1].text not in ACCESS:
            raise SourceError(rest[1].line, rest[1].col,
                              f"unknown access mode '{rest[1].text}' for external '{name.text}' "
                              f"(expected read, write or readwrite)")
        var = Var("external", name.text, rest[0].text, (name.line, name.col), access=rest[1].text)
        var.type_pos = (rest[0].line, rest[0].col)
        self.declare(var, name)

    def kw_local(self, toks, raw):
        name, rest = self.declaration_head(toks, "local")
        eq = next((i for i, t in enumerate(rest) if t.is_op("=")), None)
        if eq is None:
            self.usage(toks[0], "local")
        ctype = parse_type(rest[:eq], (rest[eq].line, rest[eq].col), allow_ref=False)
        if ctype.const:
            raise SourceError(*ctype.pos, "a local cannot be const (restart assigns its initial value again)")
        init = parse_initial_value(rest[eq + 1:], _end_of(rest, rest[eq].line, raw))
        self.declare(Var("local", name.text, ctype, (name.line, name.col), init=init), name)

    def kw_parameter(self, toks, raw):
        name, rest = self.declaration_head(toks, "parameter")
        if any(t.is_op("=") for t in rest):
            self.usage(toks[0], "parameter")
        ctype = parse_type(rest, _end_of(rest, name.line, raw), allow_ref=True)
        self.declare(Var("parameter", name.text, ctype, (name.line, name.col)), name)

    def declare(self, var, tok):
        check_name(tok, "variable", self.diags, reserved=True)  # kept even if refused: no follow-on errors
        other = self.model.variables.get(var.name)
        if other is not None:
            raise SourceError(tok.line, tok.col, f"duplicate variable '{var.name}' (first declared on line {other.line})")
        self.model.variables[var.name] = var

    # -- states --
    def kw_state(self, toks, raw):
        first = toks[0]
        if self.state is not None:
            self.diags.error(first.line, first.col, f"state '{self.state.name}' (line {self.state.line}) is not closed with 'end'")
        ok = 2 <= len(toks) <= 3 and toks[1].kind == "ident" and (len(toks) == 2 or toks[2].is_word("initial"))
        if not ok:
            self.state = State("?", (first.line, first.col), False)
            self.usage(first, "state")
        name = toks[1]
        self.state = State(name.text, (first.line, first.col), len(toks) == 3)
        check_name(name, "state", self.diags, length=True)  # kept even if refused: no follow-on errors
        for other in self.model.states:
            if other.name == name.text:
                raise SourceError(first.line, first.col, f"duplicate state '{name.text}' (first declared on line {other.line})")
        self.model.states.append(self.state)

    def kw_end(self, toks, raw):
        if len(toks) != 1:
            self.usage(toks[1], "end")
        if self.state is None:
            raise SourceError(toks[0].line, toks[0].col, "'end' outside a state")
        self.state = None

    def transition(self, toks, raw):
        first = toks[0]
        if self.state is None:
            raise SourceError(first.line, first.col, "transition outside a state")
        if len(toks) < 3 or toks[1].kind != "ident" or not toks[2].is_word("when"):
            self.usage(first, "transition")
        guard = parse_guard(toks[3:], _end_of(toks, first.line, raw))
        self.state.transitions.append(Transition(toks[1].text, (toks[1].line, toks[1].col), guard,
                                                 (first.line, first.col)))

    def kw_submachine(self, toks, raw):
        first = toks[0]
        if self.state is None:
            raise SourceError(first.line, first.col, "a submachine belongs to a state")
        if not 2 <= len(toks) <= 3 or toks[1].kind != "ident" or (len(toks) == 3 and toks[2].kind != "ident"):
            self.usage(first, "submachine")
        mode = toks[2].text if len(toks) == 3 else "restart"
        if mode not in ("restart", "resume"):
            raise SourceError(toks[2].line, toks[2].col,
                              f"unknown submachine entry mode '{mode}' (expected restart or resume)")
        if self.state.submachine is not None:
            raise SourceError(first.line, first.col,
                              f"state '{self.state.name}' already owns submachine '{self.state.submachine[0]}'")
        if check_name(toks[1], "machine", self.diags, length=True):
            self.state.submachine = (toks[1].text, mode, (toks[1].line, toks[1].col))

    # -- verification (read by the Promela back end only) --
    def kw_assume(self, toks, raw):
        first = toks[0]
        end = _end_of(toks, first.line, raw)
        rest = toks[1:]
        kind = "domain"
        if rest and rest[0].is_word("call"):
            kind, rest = "call", rest[1:]
        split = next((i for i, t in enumerate(rest) if t.is_word("in") or t.is_op("=")), None)
        if split is None or split == 0 or split + 1 >= len(rest):
            self.usage(first, "assume")
        if rest[split].is_op("="):
            if kind == "call":
                self.usage(first, "assume")
            kind = "value"
        target = parse_guard(rest[:split], (rest[split].line, rest[split].col))
        values = parse_initial_value(rest[split + 1:], end)
        if kind != "value" and not hasattr(values, "items"):
            raise SourceError(rest[split + 1].line, rest[split + 1].col, "expected a set of values '{a, b, ...}'")
        self.model.assumes.append(Assume(kind, target, values, (first.line, first.col)))

    def property(self, toks, raw, kind):
        first = toks[0]
        if len(toks) < 4 or toks[1].kind != "ident" or not toks[2].is_op(":"):
            self.usage(first, kind)
        check_name(toks[1], "property", self.diags)
        for other in self.model.properties:
            if other.name == toks[1].text:
                raise SourceError(toks[1].line, toks[1].col,
                                  f"duplicate property '{other.name}' (first declared on line {other.pos[0]})")
        end = _end_of(toks, first.line, raw)
        tree = parse_ltl(toks[3:], end)  # an assert may name states too; the back end refuses [] <> U there
        self.model.properties.append(Property(kind, toks[1].text, tree, (first.line, first.col)))

    def kw_ltl(self, toks, raw):
        self.property(toks, raw, "ltl")

    def kw_assert(self, toks, raw):
        self.property(toks, raw, "assert")

    # -- code blocks --
    def code_block(self, k, section, col, brace):
        lineno, raw = k + 1, self.lines[k]
        if section not in ACTIONS:
            self.diags.error(lineno, col, f"unknown section '{section}' (expected one of {', '.join(ACTIONS)})")
        if self.state is None:
            self.diags.error(lineno, col, f"'{section}' outside a state")
        if brace < 0:
            self.diags.error(lineno, col, f"expected '{section} {{' on one line")
            raise Abort()
        start = self.offsets[k] + brace + 1
        try:
            end, tokens = scan_block(self.text, start, self.pos)
        except SourceError as e:
            self.diags.add(e)
            raise Abort()
        if end < 0:
            self.diags.error(lineno, col, f"'{section}' block is not closed")
            raise Abort()
        end_line = self.pos(end - 1)[0]  # 1-based line of the closing brace
        rest = self.text[end:self.offsets[end_line] - 1 if end_line < len(self.lines) else len(self.text)]
        stripped = rest.strip()
        if stripped and not stripped.startswith("//") and not stripped.startswith("#"):
            at = len(rest) - len(rest.lstrip())
            self.diags.error(*self.pos(end + at), "nothing may follow the '}' closing a code block")
        if self.state is not None and section in ACTIONS:
            if section in self.state.actions:
                self.diags.error(lineno, col, f"state '{self.state.name}' has two '{section}' sections")
            same_line = self.text[start:self.offsets[lineno]].strip()
            first_line = lineno if same_line else lineno + 1
            code = self.text[start:end - 1]
            if not same_line:
                code = code.split("\n", 1)[1] if "\n" in code else ""
            self.state.actions[section] = Action(first_line, code, tokens)
        return end_line


def parse_model(text, diags):
    return ModelParser(text, diags).parse()
