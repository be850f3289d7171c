"""Syntax trees of guards, initial values and C++ types, and their printing back to C++.

Every node carries the 1-based source position (line, col) of its first token. The trees are
the model's meaning: the generated C++ and the diagrams are printed from them, never pasted from
the model text, and a later back end (Promela for spin) walks the same trees.
Explicit parentheses are kept (Paren) so that printing reproduces the model's grouping.
"""

from dataclasses import dataclass, field, fields

# Binary operators by C++ precedence, loosest first; all left-associative.
BINARY_LEVELS = (("||",), ("&&",), ("|",), ("^",), ("&",), ("==", "!="), ("<", "<=", ">", ">="),
                 ("<<", ">>"), ("+", "-"), ("*", "/", "%"))
UNARY_OPS = ("!", "-", "+", "~")
CHRONO_SUFFIXES = ("h", "min", "s", "ms", "us", "ns")


@dataclass(frozen=True)
class Node:
    pos: tuple = field(compare=False)  # (line, col)


@dataclass(frozen=True)
class BoolLit(Node):
    value: bool


@dataclass(frozen=True)
class NumberLit(Node):
    """An integer, floating or std::chrono literal, printed as written (`0x1F`, `1'000`, `2.5e-3`)."""
    text: str
    kind: str  # "int", "float" or "duration"
    suffix: str = ""  # for durations the chrono unit: h min s ms us ns


@dataclass(frozen=True)
class Name(Node):
    """A variable (one part) or a ::-qualified constant (several parts; `rooted` for a leading ::)."""
    parts: tuple
    rooted: bool = False


@dataclass(frozen=True)
class Member(Node):
    obj: Node
    field: str


@dataclass(frozen=True)
class Index(Node):
    obj: Node
    index: Node


@dataclass(frozen=True)
class Unary(Node):
    op: str  # one of UNARY_OPS (`not` is read as `!`)
    operand: Node


@dataclass(frozen=True)
class Binary(Node):
    op: str  # one of BINARY_LEVELS (`and`/`or` are read as `&&`/`||`)
    left: Node
    right: Node


@dataclass(frozen=True)
class Conditional(Node):
    cond: Node
    then: Node
    otherwise: Node


@dataclass(frozen=True)
class Call(Node):
    """after(d) or after_ms(n): the only calls a guard may make."""
    function: str
    args: tuple


@dataclass(frozen=True)
class Cast(Node):
    """static_cast<type>(operand)."""
    type: "Type"
    operand: Node


@dataclass(frozen=True)
class Paren(Node):
    expr: Node


@dataclass(frozen=True)
class BraceList(Node):
    """{a, b, ...}: only as a whole initial value."""
    items: tuple


# --- types ----------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Type(Node):
    """A C++ type from the allow-list grammar (behaviour/README.md):
    kind "fundamental": words, e.g. ("unsigned", "long");
    kind "named": a ::-qualified name (parts), e.g. std::int32_t or ringlet::behaviour::WaypointMission;
    kind "array": std::array<element, size>.
    `const` and `ref` (a trailing &) wrap any of them."""
    kind: str
    words: tuple = ()
    parts: tuple = ()
    rooted: bool = False
    element: "Type" = None
    size: Node = None
    const: bool = False
    ref: bool = False

    def without_ref(self):
        return Type(self.pos, self.kind, self.words, self.parts, self.rooted, self.element, self.size,
                    self.const, False)


def print_type(t):
    if t.kind == "fundamental":
        base = " ".join(t.words)
    elif t.kind == "named":
        base = ("::" if t.rooted else "") + "::".join(t.parts)
    else:
        base = f"std::array<{print_type(t.element)}, {print_expr(t.size)}>"
    return ("const " if t.const else "") + base + ("&" if t.ref else "")


# --- printing -------------------------------------------------------------------------------------

def print_expr(e):
    """C++ text of an expression tree, with the spacing the shipped models use (`a && b`, `!x`)."""
    if isinstance(e, BoolLit):
        return "true" if e.value else "false"
    if isinstance(e, NumberLit):
        return e.text
    if isinstance(e, Name):
        return ("::" if e.rooted else "") + "::".join(e.parts)
    if isinstance(e, Member):
        return f"{print_expr(e.obj)}.{e.field}"
    if isinstance(e, Index):
        return f"{print_expr(e.obj)}[{print_expr(e.index)}]"
    if isinstance(e, Unary):
        operand = print_expr(e.operand)
        # `- -x` must not become the decrement `--x`.
        space = " " if e.op in "+-" and operand[:1] == e.op else ""
        return e.op + space + operand
    if isinstance(e, Binary):
        return f"{print_expr(e.left)} {e.op} {print_expr(e.right)}"
    if isinstance(e, Conditional):
        return f"{print_expr(e.cond)} ? {print_expr(e.then)} : {print_expr(e.otherwise)}"
    if isinstance(e, Call):
        return f"{e.function}(" + ", ".join(print_expr(a) for a in e.args) + ")"
    if isinstance(e, Cast):
        return f"static_cast<{print_type(e.type)}>({print_expr(e.operand)})"
    if isinstance(e, Paren):
        return f"({print_expr(e.expr)})"
    if isinstance(e, BraceList):
        return "{" + ", ".join(print_expr(i) for i in e.items) + "}"
    raise TypeError(f"not an expression node: {e!r}")


def children(e):
    """The sub-expressions of a node (types excluded), for walks."""
    out = []
    for f in fields(e):
        v = getattr(e, f.name)
        if isinstance(v, Node) and not isinstance(v, Type):
            out.append(v)
        elif isinstance(v, tuple):
            out.extend(x for x in v if isinstance(x, Node))
    return out


def walk(e):
    """Every node of the tree, parents before children (iterative: trees may be deep)."""
    stack = [e]
    while stack:
        node = stack.pop()
        yield node
        stack.extend(reversed(children(node)))
