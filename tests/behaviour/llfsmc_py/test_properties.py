"""Property-based tests of llfsmc with Hypothesis (Debian: python3-hypothesis), derandomized so
that every run checks the same examples:

  * guards generated from the grammar parse, print and parse again to the same tree, and the
    printed text is a fixed point;
  * the parser groups binary operators as C++ does (an independent precedence table below);
  * models mutated at random (tokens deleted, inserted, replaced; random bytes; lines swapped,
    truncation) never make llfsmc raise: it either compiles the model and writes every output,
    or prints only `model:LINE:COL: error: ...` lines inside the file, and exits with 1.
"""

import os
import unittest

try:
    from hypothesis import HealthCheck, assume, given, settings
    from hypothesis import strategies as st
except ImportError as exc:  # a clear failure, not a skip: the package is a build dependency
    raise ImportError("python3-hypothesis is not installed (apt-get install python3-hypothesis; "
                      "tools/ringlet installs the host packages)") from exc

import support
from llfsmc import syntax as S
from llfsmc.diagnostics import SourceError
from llfsmc.expr_parser import parse_guard
from llfsmc.lexer import lex_line

SETTINGS = dict(derandomize=True, deadline=None, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])

# --- guards from the grammar ------------------------------------------------------------------------

space = st.sampled_from(["", " ", "  ", "\t"])
names = st.sampled_from(["a", "b", "n", "ball", "ringlet::wb::FsmCommand::kSuspend", "::ns::kLimit"])
numbers = st.sampled_from(["0", "1", "42u", "0x1F", "1'000", "2.5", ".5", "1e-3", "3.0f", "250ms", "2s", "1.5min"])
leaves = st.one_of(names, numbers, st.sampled_from(["true", "false", "ball.visible", "ball.x", "v[2]"]))
BINARY = [op for level in S.BINARY_LEVELS for op in level]


def grow(kids):
    return st.one_of(
        st.tuples(kids, space, st.sampled_from(BINARY + ["and", "or"]), space, kids).map(
            lambda t: f"{t[0]} {t[2]} {t[4]}" if t[2] in ("and", "or") else "".join(t)),
        st.tuples(st.sampled_from(["!", "-", "+", "~", "not "]), kids).map(lambda t: f"{t[0]} {t[1]}"),
        st.tuples(space, kids, space).map(lambda t: f"({t[0]}{t[1]}{t[2]})"),
        st.tuples(kids, kids, kids).map(lambda t: f"{t[0]} ? {t[1]} : {t[2]}"),
        kids.map(lambda k: f"static_cast<double>({k})"),
        kids.map(lambda k: f"after_ms({k})"),
        st.tuples(kids, st.sampled_from(["x", "valid"])).map(lambda t: f"({t[0]}).{t[1]}"),
        st.tuples(kids, kids).map(lambda t: f"({t[0]})[{t[1]}]"),
    )


guards = st.recursive(leaves, grow, max_leaves=24)


def parse(text):
    return parse_guard(lex_line(text, 1), (1, len(text) + 1))


class GuardRoundTrip(unittest.TestCase):
    @settings(max_examples=400, **SETTINGS)
    @given(guards)
    def test_parse_print_parse(self, text):
        try:
            tree = parse(text)
        except SourceError as e:
            assume("nested too deeply" not in e.message and "too long" not in e.message)
            raise AssertionError(f"grammar-generated guard refused: {text!r}: {e.line}:{e.col}: {e.message}")
        printed = S.print_expr(tree)
        again = parse(printed)
        self.assertEqual(again, tree, f"{text!r} printed as {printed!r}")
        self.assertEqual(S.print_expr(again), printed)

    @settings(max_examples=300, **SETTINGS)
    @given(st.lists(st.sampled_from(BINARY), min_size=2, max_size=2))
    def test_binary_grouping_is_cxx(self, ops):
        # C++ precedence, loosest first (cppreference), written independently of syntax.py.
        cxx = [["||"], ["&&"], ["|"], ["^"], ["&"], ["==", "!="], ["<", "<=", ">", ">="], ["<<", ">>"],
               ["+", "-"], ["*", "/", "%"]]
        rank = {op: i for i, level in enumerate(cxx) for op in level}
        tree = parse(f"a {ops[0]} b {ops[1]} c")
        if rank[ops[1]] > rank[ops[0]]:
            self.assertEqual((tree.op, tree.right.op), (ops[0], ops[1]))  # a op0 (b op1 c)
        else:
            self.assertEqual((tree.op, tree.left.op), (ops[1], ops[0]))  # (a op0 b) op1 c


# --- mutated models ---------------------------------------------------------------------------------

def _read(path):
    with open(path, "rb") as f:
        return f.read()


MODELS = [_read(p) for p in support.model_paths()]
SNIPPETS = [b"{", b"}", b"(", b")", b"[", b"]", b"/*", b"*/", b"//", b"\"", b"'", b"#", b"\\\n", b"\n",
            b"->", b" when ", b"state ", b"end", b"initial", b"OnEntry {", b"local ", b"external ",
            b"parameter ", b"machine ", b":", b"=", b"==", b"++", b",", b";", b"after(", b"1'0", b"R\"x(",
            b")x\"", b"class", b"__x", b"std::array<int, 3>", b"&", b"*", b"\x00", b"\xff", b"\xc3",
            b"\xe2\x82\xac", b"\r\n", b"\t", b" ", b"0x", b"1e", b"ringlet::wb::", b".", b"<%", b"%:"]
edits = st.tuples(st.sampled_from(["delete", "insert", "replace", "byte", "swap", "truncate", "duplicate"]),
                  st.integers(0, 1 << 20), st.integers(0, 1 << 20),
                  st.sampled_from(SNIPPETS), st.integers(0, 255))


def mutate(data, edit):
    kind, where, other, snippet, byte = edit  # where, other: positions modulo the size
    i = where % (len(data) + 1)
    j = min(len(data), i + 1 + other % 12)
    if kind == "delete":
        return data[:i] + data[j:]
    if kind == "insert":
        return data[:i] + snippet + data[i:]
    if kind == "replace":
        return data[:i] + snippet + data[j:]
    if kind == "byte":
        return data[:i] + bytes([byte]) + data[i + 1:]
    if kind == "truncate":
        return data[:i]
    lines = data.split(b"\n")
    a, b = where % len(lines), other % len(lines)
    if kind == "swap":
        lines[a], lines[b] = lines[b], lines[a]
    else:
        lines.insert(b, lines[a])
    return b"\n".join(lines)


class MutatedModels(unittest.TestCase):
    def check_outcome(self, data):
        status, err, path, produced = support.compile_bytes(data)
        if status == 0:
            self.assertEqual(err, [])
            self.assertTrue(produced, "exit 0 without every output")
            return
        self.assertEqual(status, 1, err)
        self.assertTrue(err, "exit 1 without a message")
        self.assertFalse(produced, "outputs written although the model was refused")
        line_count = data.count(b"\n") + 1
        for line in err:
            problem = support.error_shape_problem(line, path, line_count)
            self.assertIsNone(problem, f"{problem}: {line!r}")

    @settings(max_examples=500, **SETTINGS)
    @given(st.sampled_from(range(len(MODELS))), st.lists(edits, min_size=1, max_size=4))
    def test_mutants_compile_or_fail_with_positions(self, which, mutations):
        data = MODELS[which]
        for edit in mutations:
            data = mutate(data, edit)
        self.check_outcome(data)

    @settings(max_examples=100, **SETTINGS)
    @given(st.binary(max_size=300))
    def test_random_bytes(self, data):
        self.check_outcome(data)

    @settings(max_examples=100, **SETTINGS)
    @given(st.sampled_from(range(len(MODELS))), st.binary(min_size=1, max_size=40), st.integers(0, 1 << 20))
    def test_random_bytes_inside_models(self, which, junk, where):
        data = MODELS[which]
        i = where % (len(data) + 1)
        self.check_outcome(data[:i] + junk + data[i:])

    def test_the_unmutated_models_compile(self):
        for data in MODELS:
            status, err, _, produced = support.compile_bytes(data)
            self.assertEqual((status, err, produced), (0, [], True))


if __name__ == "__main__":
    unittest.main()
