"""Parsers for what verification reads beyond guards: LTL formulas of `ltl` lines and the
expressions of action code (which may call a few pure library functions).

Both extend the guard grammar (expr_parser.Parser), so they produce the same syntax trees plus:
  * Temporal(op, operands): `[]` (always), `<>` (eventually), `U` (until), `->` (implication);
  * InState(machine, state): `at(State)` in a machine's file, `at(Machine, State)` in a schedule;
  * Call(function, args) for `std::clamp/min/max/abs/fabs` and other `ns::f(...)` calls in action
    code (the translator decides which it can translate and which it abstracts).
"""

from dataclasses import dataclass

from . import syntax as S
from .diagnostics import SourceError
from .expr_parser import Parser


@dataclass(frozen=True)
class Temporal(S.Node):
    op: str  # "[]", "<>", "U", "->", "!"
    operands: tuple


@dataclass(frozen=True)
class InState(S.Node):
    machine: str  # "" in a machine's own file
    state: str


class LtlParser(Parser):
    """formula := implication; implication := until ['->' implication];
    until := or ['U' or]; unary adds `[]`, `<>`, `at(...)`. Everything else is the guard grammar,
    so `a && b` inside an atom and between temporal operands mean the same thing."""

    def __init__(self, tokens, end):
        # '->' would be refused as member access by the guard grammar: it becomes an operator the
        # guard grammar does not know, so an atom ends there.
        from .lexer import Token
        tokens = [Token("op", "=>", t.line, t.col) if t.is_op("->") else t for t in tokens]
        super().__init__(tokens, end, "property")

    def formula(self):
        left = self.until()
        t = self.peek()
        if t is not None and t.is_op("=>"):
            self.k += 1
            right = self.formula()
            return Temporal(left.pos, "->", (left, right))
        return left

    def until(self):
        left = self.expression()
        t = self.peek()
        if t is not None and t.is_word("U"):
            self.k += 1
            right = self.expression()
            return Temporal(left.pos, "U", (left, right))
        return left

    def unary(self):
        t, n = self.peek(), self.peek(1)
        if t is not None and n is not None and ((t.is_op("[") and n.is_op("]")) or (t.is_op("<") and n.is_op(">"))):
            self.k += 2
            self.nest(t)
            operand = self.unary()
            self.depth -= 1
            return Temporal((t.line, t.col), t.text + n.text, (operand,))
        if t is not None and t.is_op("("):
            # A parenthesised sub-formula may hold temporal operators and '->'.
            self.k += 1
            inner = self.formula()
            self.expect_op(")", "closing the '('")
            return self.make(S.Paren((t.line, t.col), inner), t)
        if t is not None and t.is_word("at") and n is not None and n.is_op("("):
            self.k += 2
            first = self.take()
            names = [first]
            if self.peek() is not None and self.peek().is_op(","):
                self.k += 1
                names.append(self.take())
            self.expect_op(")", "closing at(...)")
            if any(x.kind != "ident" for x in names):
                raise SourceError(t.line, t.col, "expected at(State) or at(Machine, State)")
            machine = names[0].text if len(names) == 2 else ""
            return InState((t.line, t.col), machine, names[-1].text)
        return super().unary()


def parse_ltl(tokens, end):
    p = LtlParser(tokens, end)
    if p.at_end():
        raise SourceError(*end, "empty property")
    node = p.formula()
    return p.finish(node)


class ActionParser(Parser):
    """Expressions of action code: the guard grammar plus calls of qualified functions
    (`std::clamp(a, lo, hi)`); after()/after_ms() are refused (they belong in guards)."""

    def __init__(self, tokens, end):
        super().__init__(tokens, end, "action expression")

    def postfix(self):
        t0 = self.peek()
        if t0 is not None and (t0.kind == "ident" or t0.is_op("::")):
            save = self.k
            rooted, parts = self.qualified_name()
            t = self.peek()
            if t is not None and t.is_op("(") and (len(parts) > 1 or parts[0] in ("after", "after_ms")):
                self.k += 1
                args = []
                if not (self.peek() is not None and self.peek().is_op(")")):
                    args.append(self.expression())
                    while self.peek() is not None and self.peek().is_op(","):
                        self.k += 1
                        args.append(self.expression())
                self.expect_op(")", "closing a call's arguments")
                return S.Call((t0.line, t0.col), "::".join(parts), tuple(args))
            self.k = save
        return super().postfix()


def parse_action_expr(tokens, end):
    p = ActionParser(tokens, end)
    if p.at_end():
        raise SourceError(*end, "empty expression")
    return p.finish(p.expression())
