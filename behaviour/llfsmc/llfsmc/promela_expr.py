"""Expressions to Promela: C++ values become Promela ints.

Why fixed point: Promela has integers only. A double is an int counting thousandths (SCALE), so
every declared value must be a multiple of 0.001 (refused otherwise); `*` and `/` of two doubles
rescale and truncate towards zero like C's integer division. bool is bool, integers and enums
(their index in schema.def) are ints.
"""

from decimal import Decimal, InvalidOperation

from . import syntax as S
from .diagnostics import SourceError

SCALE = 1000
DOUBLE_WORDS = ("double", "float")


class Untranslatable(Exception):
    """Why an expression has no Promela counterpart (the caller names machine, state, line)."""

    def __init__(self, pos, why):
        super().__init__(why)
        self.pos, self.why = pos, why


def fixed_literal(text, pos):
    """A C++ floating literal as thousandths; refuses what is not a multiple of 0.001."""
    t = text.replace("'", "").rstrip("fFlL")
    try:
        v = Decimal(t) * SCALE
    except InvalidOperation:
        raise Untranslatable(pos, f"'{text}' is not a number Promela can hold")
    if v != v.to_integral_value():
        raise Untranslatable(pos, f"'{text}' is not a multiple of 0.001 (doubles are fixed point in thousandths)")
    return int(v)


def int_literal(text, pos):
    t = text.replace("'", "").rstrip("uUlLzZ")
    try:
        return int(t, 0) if not (len(t) > 1 and t[0] == "0" and t[1].isdigit()) else int(t, 8)
    except ValueError:
        raise Untranslatable(pos, f"'{text}' is not an integer Promela can hold")


def convert(text, have, want):
    """`text` of Promela type `have` as `want` ('bool', 'int', 'fixed')."""
    if have == want or want is None:
        return text
    if want == "fixed" and have in ("int", "bool"):
        return f"(({text}) * {SCALE})"
    if want == "int" and have == "fixed":
        return f"(({text}) / {SCALE})"
    if want == "bool":
        return f"(({text}) != 0)"
    return text


def literal(value, ptype, pos):
    """A declared value (a syntax tree of a literal, maybe negated, or an enumerator) -> int."""
    neg = False
    while isinstance(value, (S.Unary, S.Paren)):
        if isinstance(value, S.Paren):
            value = value.expr
            continue
        if value.op not in "+-":
            break
        neg ^= value.op == "-"
        value = value.operand
    if isinstance(value, S.BoolLit):
        v = int(value.value)
    elif isinstance(value, S.NumberLit) and value.kind != "duration":
        if ptype == "fixed":
            v = fixed_literal(value.text, value.pos)
        elif value.kind == "float":
            raise Untranslatable(value.pos, f"'{value.text}' is not an integer")
        else:
            v = int_literal(value.text, value.pos)
    else:
        raise SourceError(*value.pos, "a declared value must be a literal (number, true, false)")
    return -v if neg else v


class ExprTranslator:
    """Walks a syntax tree; `resolve(node)` (given by the caller) turns a Name/Member into
    (promela text, type) or raises Untranslatable; `call(node)` likewise for Call nodes."""

    def __init__(self, resolve, call, enums):
        self.resolve, self.call, self.enums = resolve, call, enums

    def tx(self, e, want=None):
        text, have = self.value(e)
        return convert(text, have, want)

    def value(self, e):
        if isinstance(e, S.BoolLit):
            return ("true" if e.value else "false"), "bool"
        if isinstance(e, S.NumberLit):
            if e.kind == "duration":
                raise Untranslatable(e.pos, "a chrono literal outside after()")
            if e.kind == "float":
                return str(fixed_literal(e.text, e.pos)), "fixed"
            return str(int_literal(e.text, e.pos)), "int"
        if isinstance(e, S.Paren):
            t, ty = self.value(e.expr)
            return f"({t})", ty
        if isinstance(e, S.Name) and len(e.parts) == 4 and e.parts[:2] == ("ringlet", "wb") \
                and e.parts[2] in self.enums:
            return str(self.enums[e.parts[2]].index(e.parts[3])), "int"
        if isinstance(e, (S.Name, S.Member, S.Index)):
            return self.resolve(e)
        if isinstance(e, S.Unary):
            t, ty = self.value(e.operand)
            if e.op == "!":
                return f"!({convert(t, ty, 'bool')})", "bool"
            if e.op == "-":
                return f"-({t})", ("int" if ty == "bool" else ty)
            if e.op == "+":
                return t, ty
            raise Untranslatable(e.pos, f"operator '{e.op}'")
        if isinstance(e, S.Binary):
            return self.binary(e)
        if isinstance(e, S.Conditional):
            c = self.tx(e.cond, "bool")
            a, ta = self.value(e.then)
            b, tb = self.value(e.otherwise)
            ty = "fixed" if "fixed" in (ta, tb) else ("int" if "int" in (ta, tb) else "bool")
            return f"({c} -> {convert(a, ta, ty)} : {convert(b, tb, ty)})", ty
        if isinstance(e, S.Cast):
            t, ty = self.value(e.operand)
            words = e.type.words if e.type.kind == "fundamental" else e.type.parts
            want = "bool" if words == ("bool",) else ("fixed" if any(w in DOUBLE_WORDS for w in words) else "int")
            return convert(t, ty, want), want
        if isinstance(e, S.Call):
            return self.call(e)
        raise Untranslatable(e.pos, f"'{S.print_expr(e)}' has no Promela counterpart")

    def binary(self, e):
        a, ta = self.value(e.left)
        b, tb = self.value(e.right)
        op = e.op
        if op in ("&&", "||"):
            return f"({convert(a, ta, 'bool')} {op} {convert(b, tb, 'bool')})", "bool"
        ty = "fixed" if "fixed" in (ta, tb) else "int"
        a, b = convert(a, ta, ty), convert(b, tb, ty)
        if op in ("==", "!=", "<", "<=", ">", ">="):
            return f"({a} {op} {b})", "bool"
        if op in ("+", "-"):
            return f"({a} {op} {b})", ty
        if op == "*":
            return (f"(({a} * {b}) / {SCALE})" if ty == "fixed" else f"({a} * {b})"), ty
        if op == "/":
            return (f"(({a} * {SCALE}) / {b})" if ty == "fixed" else f"({a} / {b})"), ty
        if op == "%" and ty == "int":
            return f"({a} % {b})", "int"
        raise Untranslatable(e.pos, f"operator '{op}' on these operands")
