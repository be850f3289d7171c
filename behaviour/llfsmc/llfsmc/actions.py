"""Action code as statements, for the Promela back end: splits a code block's tokens into
statements and says what each one does (assigns which variable, from which expression), without
deciding whether it can be translated (abstraction.py does).

Statement kinds (Stmt.kind):
  assign   lhs op rhs;            target = (name, field or None), op one of = += -= *= /=
  incr     ++x; x++; --x; x--;    target, op "+=" / "-="
  temp     [const] T name = rhs;  a block-local constant (target = (name, None))
  request  suspend_machine("M");  resume_machine / restart_machine likewise
  if       if (cond) body [else body]
  opaque   anything else, and a whole loop (`for (...) body`, `while (...) body`) (a call statement, a declaration without '=' ...): what it writes is not
           known; it may only be dropped when it names nothing the properties depend on
"""

from .diagnostics import SourceError

ASSIGN_OPS = ("=", "+=", "-=", "*=", "/=")
REQUESTS = {"suspend_machine": "suspend", "resume_machine": "resume", "restart_machine": "restart"}


class Stmt:
    def __init__(self, kind, line, tokens, target=None, op=None, rhs=None, cond=None, body=(), orelse=(),
                 machine=None):
        self.kind, self.line, self.tokens = kind, line, tokens
        self.target, self.op, self.rhs = target, op, rhs
        self.cond, self.body, self.orelse, self.machine = cond, list(body), list(orelse), machine

    @property
    def text(self):
        return " ".join(t.text for t in self.tokens)


def _match(tokens, k, open_, close):
    """Index of the token closing tokens[k] (an `open_`)."""
    depth = 0
    for j in range(k, len(tokens)):
        if tokens[j].is_op(open_):
            depth += 1
        elif tokens[j].is_op(close):
            depth -= 1
            if depth == 0:
                return j
    raise SourceError(tokens[k].line, tokens[k].col, f"unbalanced '{open_}'")


def _statement_end(tokens, k):
    """Index of the ';' ending the simple statement that starts at k (nesting respected)."""
    depth = 0
    for j in range(k, len(tokens)):
        t = tokens[j]
        if t.is_op("(", "[", "{", "<%"):
            depth += 1
        elif t.is_op(")", "]", "}", "%>"):
            depth -= 1
        elif t.is_op(";") and depth == 0:
            return j
    raise SourceError(tokens[k].line, tokens[k].col, "statement without ';'")


def _lvalue(tokens):
    """(name, field) for `x` or `x.f`, else None."""
    if len(tokens) == 1 and tokens[0].kind == "ident":
        return tokens[0].text, None
    if len(tokens) == 3 and tokens[0].kind == "ident" and tokens[1].is_op(".") and tokens[2].kind == "ident":
        return tokens[0].text, tokens[2].text
    return None


def _simple(tokens):
    line = tokens[0].line
    first = tokens[0]
    if first.is_op("++", "--"):
        lv = _lvalue(tokens[1:])
        if lv:
            return Stmt("incr", line, tokens, target=lv, op="+=" if first.text == "++" else "-=")
    if tokens[-1].is_op("++", "--"):
        lv = _lvalue(tokens[:-1])
        if lv:
            return Stmt("incr", line, tokens, target=lv, op="+=" if tokens[-1].text == "++" else "-=")
    if first.kind == "ident" and first.text in REQUESTS and len(tokens) == 4 and tokens[1].is_op("(") \
            and tokens[2].kind == "string" and tokens[3].is_op(")") and tokens[2].text.startswith('"'):
        return Stmt("request", line, tokens, op=REQUESTS[first.text], machine=tokens[2].text[1:-1])
    depth = 0
    for j, t in enumerate(tokens):
        if t.is_op("(", "[", "{", "<"):
            depth += 1 if not t.is_op("<") else 0
        elif t.is_op(")", "]", "}"):
            depth -= 1
        elif depth == 0 and t.kind == "op" and t.text in ASSIGN_OPS:
            lhs, rhs = tokens[:j], tokens[j + 1:]
            lv = _lvalue(lhs)
            if lv:
                return Stmt("assign", line, tokens, target=lv, op=t.text, rhs=rhs)
            if t.text == "=" and len(lhs) >= 2 and lhs[-1].kind == "ident":
                return Stmt("temp", line, tokens, target=(lhs[-1].text, None), rhs=rhs)
            break
    # `T name{...};` / `T name;`: a declaration whose value is not an expression we read.
    if len(tokens) >= 2 and tokens[-1].is_op("}"):
        k = next((i for i, t in enumerate(tokens) if t.is_op("{")), None)
        if k and tokens[k - 1].kind == "ident":
            return Stmt("temp", line, tokens, target=(tokens[k - 1].text, None), rhs=None)
    return Stmt("opaque", line, tokens)


def split_statements(tokens):
    """The statements of a code block (tokens without comments, as lexer.scan_block gives)."""
    out, k = [], 0
    while k < len(tokens):
        t = tokens[k]
        if t.is_op(";"):
            k += 1
        elif t.is_op("{"):
            j = _match(tokens, k, "{", "}")
            out.extend(split_statements(tokens[k + 1:j]))
            k = j + 1
        elif t.is_word("if") and k + 1 < len(tokens) and tokens[k + 1].is_op("("):
            j = _match(tokens, k + 1, "(", ")")
            cond = tokens[k + 2:j]
            body, k = _branch(tokens, j + 1)
            orelse = []
            if k < len(tokens) and tokens[k].is_word("else"):
                orelse, k = _branch(tokens, k + 1)
            out.append(Stmt("if", t.line, [t], cond=cond, body=body, orelse=orelse))
        elif t.is_word("for", "while") and k + 1 < len(tokens) and tokens[k + 1].is_op("("):
            # A loop is one opaque statement (header and body): what it writes depends on how often
            # it runs, so the model checker only drops it (when it names nothing modelled).
            j = _match(tokens, k + 1, "(", ")")
            _, end = _branch(tokens, j + 1)
            out.append(Stmt("opaque", t.line, tokens[k:end]))
            k = end
        else:
            j = _statement_end(tokens, k)
            if j > k:
                out.append(_simple(tokens[k:j]))
            k = j + 1
    return out


def _branch(tokens, k):
    if k >= len(tokens):
        raise SourceError(tokens[-1].line, tokens[-1].col, "'if' without a statement")
    if tokens[k].is_op("{"):
        j = _match(tokens, k, "{", "}")
        return split_statements(tokens[k + 1:j]), j + 1
    if tokens[k].is_word("if"):
        # a nested if: split it as a block of its own up to its end
        stmts = split_statements(tokens[k:])
        return stmts[:1], len(tokens) if len(stmts) == 1 else _index_after(tokens, k, stmts[0])
    j = _statement_end(tokens, k)
    return [_simple(tokens[k:j])], j + 1


def _index_after(tokens, k, stmt):
    raise SourceError(tokens[k].line, tokens[k].col, "a nested 'if' without braces is not supported: use braces")
