"""Recursive-descent parser for guards, initial values and C++ types (grammar: behaviour/README.md).

Guards are side-effect-free C++ expressions over the machine's variables; anything outside the
grammar is refused with the position of the offending token and the reason (an assignment, a
call, a lambda, the comma operator...). Nesting is bounded so that no input can exhaust the stack.
"""

from .diagnostics import SourceError
from .lexer import Token
from .names import CXX_KEYWORDS, identifier_problem
from . import syntax as S

BINARY_PRECEDENCE = {op: level for level, ops in enumerate(S.BINARY_LEVELS) for op in ops}

MAX_DEPTH = 64  # nested sub-expressions (parentheses, unary operators...): bounds the recursion
MAX_TREE_DEPTH = 128  # bounds the recursion of everything that walks a tree (printing, checks)
SIDE_EFFECT_OPS = {"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>=", "++", "--"}
SIDE_EFFECT_WORDS = {"new", "delete", "throw", "co_await", "co_yield", "co_return"}
WORD_OPS = {"and": "&&", "or": "||", "not": "!", "bitand": "&", "bitor": "|", "xor": "^", "compl": "~"}
GUARD_CALLS = ("after", "after_ms")
INT_SUFFIXES = {"", "u", "l", "ul", "lu", "ll", "ull", "llu", "z", "uz", "zu"}
FLOAT_SUFFIXES = {"", "f", "l"}
FUNDAMENTAL_WORDS = {"bool", "char", "short", "int", "long", "float", "double", "signed", "unsigned",
                     "wchar_t", "char8_t", "char16_t", "char32_t"}


def _fundamental_spellings():
    out = {("bool",), ("char",), ("signed", "char"), ("unsigned", "char"), ("wchar_t",), ("char8_t",),
           ("char16_t",), ("char32_t",), ("float",), ("double",), ("long", "double")}
    for base in (("short",), ("int",), ("long",), ("long", "long")):
        out.add(base)
        for sign in (("signed",), ("unsigned",)):
            out.add(sign + base)
            if base != ("int",):
                out.add(sign + base + ("int",))
        if base != ("int",):
            out.add(base + ("int",))
    out |= {("signed",), ("unsigned",)}
    return out


FUNDAMENTAL_TYPES = _fundamental_spellings()


def classify_number(tok):
    """(kind, suffix) of a number token: kind int, float or duration; raises for malformed ones."""
    text = tok.text.replace("'", "")
    low = text.lower()
    bad = SourceError(tok.line, tok.col, f"malformed number '{tok.text}'")
    if tok.text.startswith("'") or "''" in tok.text or tok.text.endswith("'"):
        raise bad
    if low.startswith(("0x", "0b")):
        digits = "0123456789abcdef" if low[1] == "x" else "01"
        k = 2
        while k < len(low) and low[k] in digits:
            k += 1
        if k == 2 or low[k:] not in INT_SUFFIXES:
            raise bad
        return "int", low[k:]
    k, n = 0, len(text)
    while k < n and text[k].isdigit():
        k += 1
    is_float = False
    if k < n and text[k] == ".":
        is_float = True
        k += 1
        while k < n and text[k].isdigit():
            k += 1
    if k < n and text[k] in "eE":
        j = k + 1
        if j < n and text[j] in "+-":
            j += 1
        if j < n and text[j].isdigit():
            is_float = True
            k = j
            while k < n and text[k].isdigit():
                k += 1
    if k == 0 or text[:k] == ".":
        raise bad
    suffix = text[k:]
    if suffix in S.CHRONO_SUFFIXES:
        return "duration", suffix
    if is_float and suffix.lower() in FLOAT_SUFFIXES:
        return "float", suffix
    if not is_float and suffix.lower() in INT_SUFFIXES:
        if len(text) > 1 and text[0] == "0" and not all(c in "01234567" for c in text[:k]):
            raise bad
        return "int", suffix
    raise bad


class Parser:
    """Parses one expression or type from the tokens of a line; `end` is the (line, col) just past
    the last token, where "ended early" errors point. `what` names the thing for messages
    ("guard", "initial value", "type")."""

    def __init__(self, tokens, end, what):
        self.toks = list(tokens)
        self.k = 0
        self.end = end
        self.what = what
        self.depth = 0
        self.depths = {}  # id(node) -> depth of its tree
        self.keep = []  # the nodes in `depths` (so that their ids stay theirs)

    # -- token helpers --
    def peek(self, ahead=0):
        j = self.k + ahead
        return self.toks[j] if j < len(self.toks) else None

    def take(self):
        t = self.peek()
        if t is None:
            raise SourceError(*self.end, f"{self.what} ends early")
        self.k += 1
        return t

    def expect_op(self, text, context):
        t = self.peek()
        if t is not None and t.is_op(text):
            self.k += 1
            return t
        if text == ">" and t is not None and t.is_op(">>", ">=", ">>="):
            # The '>' closing a template argument list may be glued to the next one (`>>`).
            self.toks[self.k] = Token("op", t.text[1:], t.line, t.col + 1)
            return Token("op", ">", t.line, t.col)
        self.fail(t, f"expected '{text}' {context}")

    def fail(self, tok, message):
        """Raises at `tok`; a side-effect operator or a comma found there is the better reason."""
        if tok is not None and tok.kind == "op" and tok.text in SIDE_EFFECT_OPS:
            message = f"{self.what} has side effects: '{tok.text}'"
        elif tok is not None and tok.is_op(",") and self.what != "type":
            message = f"the comma operator is not allowed in a {self.what}"
        if tok is None:
            raise SourceError(*self.end, f"{self.what} ends early: {message}")
        raise SourceError(tok.line, tok.col, message)

    def at_end(self):
        return self.k >= len(self.toks)

    def finish(self, node):
        """Refuses anything after a complete expression, with the reason when there is one."""
        t = self.peek()
        if t is None:
            return node
        if t.is_op(","):
            self.fail(t, f"the comma operator is not allowed in a {self.what}")
        if t.kind == "op" and t.text in SIDE_EFFECT_OPS:
            self.fail(t, f"{self.what} has side effects: '{t.text}'")
        if t.is_op(")"):
            self.fail(t, "unmatched ')'")
        if t.is_op("("):
            self.fail(t, f"a {self.what} may only call after() and after_ms()")
        self.fail(t, f"unexpected '{t.text}' after a complete {self.what}")

    def nest(self, tok):
        self.depth += 1
        if self.depth > MAX_DEPTH:
            self.fail(tok, f"{self.what} is nested too deeply (more than {MAX_DEPTH} levels)")

    # -- expressions --
    def expression(self):
        tok = self.peek()
        self.nest(tok)
        cond = self.binary(0)
        t = self.peek()
        if t is not None and t.is_op("?"):
            self.k += 1
            then = self.expression()
            self.expect_op(":", "in a conditional expression 'c ? a : b'")
            otherwise = self.expression()
            cond = self.make(S.Conditional(cond.pos, cond, then, otherwise), t)
        self.depth -= 1
        return cond

    def binary_op(self):
        t = self.peek()
        if t is None:
            return None
        if t.kind == "op":
            return t.text
        if t.kind == "ident" and t.text in WORD_OPS and WORD_OPS[t.text] not in ("!", "~"):
            return WORD_OPS[t.text]
        return None

    def binary(self, min_level):
        """Precedence climbing over syntax.BINARY_LEVELS (all left-associative)."""
        left = self.unary()
        while True:
            op = self.binary_op()
            level = BINARY_PRECEDENCE.get(op)
            if level is None or level < min_level:
                return left
            tok = self.take()
            self.nest(tok)
            right = self.binary(level + 1)
            self.depth -= 1
            left = self.make(S.Binary(left.pos, op, left, right), tok)

    def make(self, node, tok):
        """Records the depth of a new tree node; refuses trees too deep to walk recursively (a long
        chain `a + a + ... + a` is deep without nesting)."""
        depth = 1 + max((self.depths.get(id(c), 1) for c in S.children(node)), default=0)
        if depth > MAX_TREE_DEPTH:
            self.fail(tok, f"{self.what} is too long (its syntax tree is more than {MAX_TREE_DEPTH} levels deep)")
        self.depths[id(node)] = depth
        self.keep.append(node)
        return node

    def unary(self):
        t = self.peek()
        if t is None:
            self.fail(None, "expected an operand")
        op = None
        if t.kind == "op" and t.text in S.UNARY_OPS:
            op = t.text
        elif t.is_word("not", "compl"):
            op = WORD_OPS[t.text]
        if op is None:
            if t.kind == "op" and t.text in ("++", "--"):
                self.fail(t, f"{self.what} has side effects: '{t.text}'")
            if t.is_op("&", "*") or t.is_word("bitand"):
                self.fail(t, f"unary '{t.text}' (address-of, dereference) is not allowed in a {self.what}")
            return self.postfix()
        self.k += 1
        self.nest(t)
        operand = self.unary()
        self.depth -= 1
        return self.make(S.Unary((t.line, t.col), op, operand), t)

    def postfix(self):
        node = self.primary()
        while True:
            t = self.peek()
            if t is None:
                return node
            if t.is_op("."):
                self.k += 1
                f = self.take()
                if f.kind != "ident" or f.text in CXX_KEYWORDS:
                    self.fail(f, "expected a field name after '.'")
                node = self.make(S.Member(node.pos, node, f.text), f)
            elif t.is_op("["):
                self.k += 1
                index = self.expression()
                self.expect_op("]", "closing the '['")
                node = self.make(S.Index(node.pos, node, index), t)
            elif t.is_op("("):
                if isinstance(node, S.Name) and len(node.parts) == 1 and not node.rooted and node.parts[0] in GUARD_CALLS:
                    if self.what != "guard":
                        self.fail(t, f"{node.parts[0]}() is only available in guards")
                    node = self.call(node)
                else:
                    callee = S.print_expr(node) if isinstance(node, (S.Name, S.Member)) else "..."
                    raise SourceError(*node.pos, f"{self.what} calls '{callee}()': only after() and after_ms() may be called in a guard")
            elif t.kind == "op" and t.text in ("++", "--"):
                self.fail(t, f"{self.what} has side effects: '{t.text}'")
            elif t.is_op("->", "->*", ".*"):
                self.fail(t, f"'{t.text}' is not allowed in a {self.what} (variables are values or references: use '.')")
            else:
                return node

    def call(self, name):
        self.k += 1  # '('
        args = []
        if not (self.peek() is not None and self.peek().is_op(")")):
            args.append(self.expression())
            while self.peek() is not None and self.peek().is_op(","):
                self.k += 1
                args.append(self.expression())
        self.expect_op(")", f"closing the arguments of {name.parts[0]}()")
        if len(args) != 1:
            raise SourceError(*name.pos, f"{name.parts[0]}() takes one argument, not {len(args)}")
        return self.make(S.Call(name.pos, name.parts[0], tuple(args)), self.toks[self.k - 1])

    def primary(self):
        t = self.take()
        pos = (t.line, t.col)
        if t.kind == "number":
            kind, suffix = classify_number(t)
            return S.NumberLit(pos, t.text, kind, suffix if kind == "duration" else "")
        if t.kind in ("string", "char"):
            self.fail(t, f"string and character literals are not supported in a {self.what}")
        if t.is_op("("):
            inner = self.expression()
            self.expect_op(")", "closing the '('")
            return self.make(S.Paren(pos, inner), t)
        if t.is_op("["):
            self.fail(t, f"lambdas are not allowed in a {self.what}")
        if t.is_op("{"):
            self.fail(t, f"braces are not allowed inside a {self.what}")
        if t.is_op("::") or t.kind == "ident":
            if t.is_word("true", "false"):
                return S.BoolLit(pos, t.text == "true")
            if t.is_word("static_cast"):
                return self.cast(t)
            if t.kind == "ident" and t.text in SIDE_EFFECT_WORDS:
                self.fail(t, f"{self.what} has side effects: '{t.text}'")
            if t.kind == "ident" and t.text in CXX_KEYWORDS:
                self.fail(t, f"'{t.text}' is not allowed in a {self.what}")
            self.k -= 1
            rooted, parts = self.qualified_name()
            return S.Name(pos, tuple(parts), rooted)
        if t.kind == "op" and t.text in SIDE_EFFECT_OPS:
            self.fail(t, f"{self.what} has side effects: '{t.text}'")
        self.fail(t, f"expected an operand, found '{t.text}'")

    def cast(self, t):
        self.expect_op("<", "after static_cast")
        ty = self.type(allow_ref=False)
        self.expect_op(">", "closing static_cast<")
        self.expect_op("(", "after static_cast<...>")
        self.nest(t)
        operand = self.expression()
        self.depth -= 1
        self.expect_op(")", "closing static_cast<...>(")
        return self.make(S.Cast((t.line, t.col), ty, operand), t)

    def qualified_name(self):
        """['::'] ident ('::' ident)*, every part an identifier that is not a keyword."""
        rooted = False
        if self.peek().is_op("::"):
            rooted = True
            self.k += 1
        parts = []
        while True:
            t = self.take()
            if t.kind != "ident":
                self.fail(t, f"expected a name, found '{t.text}'")
            problem = identifier_problem(t.text)
            if problem and t.text not in ("true", "false"):
                self.fail(t, f"{problem}: not usable as a name here")
            parts.append(t.text)
            nxt = self.peek()
            if nxt is None or not nxt.is_op("::"):
                return rooted, parts
            self.k += 1

    # -- types --
    def type(self, allow_ref):
        first = self.peek()
        if first is None:
            self.fail(None, "expected a type")
        pos = (first.line, first.col)
        const = False
        if first.is_word("const"):
            const = True
            self.k += 1
        t = self.peek()
        if t is None:
            self.fail(None, "expected a type")
        if t.kind == "ident" and t.text in FUNDAMENTAL_WORDS:
            words = []
            while self.peek() is not None and self.peek().kind == "ident" and self.peek().text in FUNDAMENTAL_WORDS:
                words.append(self.take().text)
            if tuple(words) not in FUNDAMENTAL_TYPES:
                raise SourceError(t.line, t.col, f"'{' '.join(words)}' is not a fundamental type")
            ty = S.Type(pos, "fundamental", words=tuple(words), const=const)
        elif t.is_op("::") or t.kind == "ident":
            if t.kind == "ident" and t.text in ("void", "auto", "decltype", "volatile", "struct", "class", "typename"):
                self.fail(t, f"'{t.text}' is not allowed in a {self.what}")
            rooted, parts = self.qualified_name()
            nxt = self.peek()
            if tuple(parts) == ("std", "array"):
                self.expect_op("<", "after std::array (std::array<T, N>)")
                element = self.type(allow_ref=False)
                if element.const:
                    raise SourceError(*element.pos, "the element type of std::array cannot be const")
                self.expect_op(",", "between the element type and the size of std::array<T, N>")
                size = self.array_size()
                self.expect_op(">", "closing std::array<T, N>")
                ty = S.Type(pos, "array", element=element, size=size, const=const)
            elif nxt is not None and nxt.is_op("<"):
                self.fail(nxt, "template arguments are only supported for std::array<T, N>")
            else:
                if len(parts) == 1:
                    raise SourceError(t.line, t.col,
                                      f"unknown type '{parts[0]}': use a fundamental type (bool, int, double...), "
                                      f"a std:: type (std::int32_t, std::size_t, std::array<T, N>) or a ::-qualified "
                                      f"type from an included header")
                ty = S.Type(pos, "named", parts=tuple(parts), rooted=rooted, const=const)
        else:
            self.fail(t, f"expected a type, found '{t.text}'")
        nxt = self.peek()
        if nxt is not None and nxt.is_word("const"):
            self.fail(nxt, "write 'const' before the type ('const T&')")
        if nxt is not None and nxt.is_op("*"):
            self.fail(nxt, "pointer types are not supported (a parameter can be a reference: T&)")
        if nxt is not None and nxt.is_op("&&"):
            self.fail(nxt, "rvalue references are not supported")
        if nxt is not None and nxt.is_op("&"):
            if not allow_ref:
                self.fail(nxt, "a reference type is only allowed for a parameter")
            self.k += 1
            ty = S.Type(ty.pos, ty.kind, ty.words, ty.parts, ty.rooted, ty.element, ty.size, ty.const, True)
        if ty.const and not ty.ref and allow_ref:
            raise SourceError(*pos, "a const parameter is a const reference: write 'const T&'")
        return ty

    def array_size(self):
        t = self.take()
        if t.kind == "number":
            kind, _ = classify_number(t)
            if kind != "int":
                self.fail(t, "the size of std::array<T, N> is an integer")
            return S.NumberLit((t.line, t.col), t.text, "int")
        if t.kind == "ident" or t.is_op("::"):
            self.k -= 1
            rooted, parts = self.qualified_name()
            return S.Name((t.line, t.col), tuple(parts), rooted)
        self.fail(t, "the size of std::array<T, N> is an integer literal or a named constant")


def parse_guard(tokens, end):
    p = Parser(tokens, end, "guard")
    if p.at_end():
        raise SourceError(*end, "empty guard")
    return p.finish(p.expression())


def parse_initial_value(tokens, end):
    """An expression, or a brace list {a, b, ...} of expressions (arrays, aggregates)."""
    p = Parser(tokens, end, "initial value")
    if p.at_end():
        raise SourceError(*end, "empty initial value")
    first = p.peek()
    if first.is_op("{"):
        p.k += 1
        items = []
        while not (p.peek() is not None and p.peek().is_op("}")):
            items.append(p.expression())
            nxt = p.peek()
            if nxt is not None and nxt.is_op(","):
                p.k += 1
            elif not (nxt is not None and nxt.is_op("}")):
                p.fail(nxt, "expected ',' or '}' in the brace list")
        p.k += 1
        return p.finish(p.make(S.BraceList((first.line, first.col), tuple(items)), first))
    return p.finish(p.expression())


def parse_type(tokens, end, allow_ref):
    p = Parser(tokens, end, "type")
    ty = p.type(allow_ref)
    t = p.peek()
    if t is not None:
        p.fail(t, f"unexpected '{t.text}' after the type")
    return ty
