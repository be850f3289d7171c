"""llfsmc front end, example by example: the action-code scanner, the guard and type grammars,
printing, and the file-level errors (no traceback, one `file: error:` line)."""

import os
import subprocess
import sys
import tempfile
import unittest

import support
from llfsmc import syntax as S
from llfsmc.diagnostics import SourceError
from llfsmc.expr_parser import parse_guard, parse_initial_value, parse_type
from llfsmc.lexer import LineMap, lex_line, scan_block


def guard(text):
    toks = lex_line(text, 1)
    return parse_guard(toks, (1, len(text) + 1))


def guard_error(text):
    try:
        guard(text)
    except SourceError as e:
        return e.col, e.message
    raise AssertionError(f"guard accepted: {text}")


def block(code):
    """(text between the braces, identifiers) of `{` + code."""
    text = "{" + code
    end, toks = scan_block(text, 1, LineMap(text))
    return (None if end < 0 else text[1:end - 1]), [t.text for t in toks if t.kind == "ident"]


class ScanBlock(unittest.TestCase):
    def test_braces_in_literals_and_comments_are_text(self):
        code = 'a = "}"; b = \'}\'; c = R"x(})x"; // }\n /* } */ d = u8"{"; }\ntail'
        body, idents = block(code)
        self.assertEqual(body, code[:code.rindex("}")])
        self.assertIn("d", idents)

    def test_nested_braces_and_digraphs(self):
        body, _ = block("if (x) { y(); } <% z(); %> }rest")
        self.assertEqual(body, "if (x) { y(); } <% z(); %> ")

    def test_digit_separator_is_not_a_character_literal(self):
        body, idents = block("n = 1'000'000; m = 'a'; }")
        self.assertEqual(body, "n = 1'000'000; m = 'a'; ")
        self.assertEqual(idents, ["n", "m"])

    def test_unclosed_block(self):
        self.assertIsNone(block("if (x) { }")[0])

    def test_refused_constructs_name_their_position(self):
        for code, line, col, words in [
            ("\n  /* open }", 2, 3, "unterminated comment"),
            ("\n s = \"abc }\n", 2, 6, "unterminated string"),
            ("\n c = '}\n", 2, 6, "unterminated character"),
            ("\n#define X }\n", 2, 1, "preprocessor"),
            ("\n x(); // \\\n }", 2, 7, "continue"),
            ("\n x = 1 + \\\n 2; }", 2, 10, "line continuation"),
            ("\n r = R\"x(never closed", 2, 7, "raw string"),
        ]:
            text = "{" + code
            with self.assertRaises(SourceError, msg=code) as cm:
                scan_block(text, 1, LineMap(text))
            self.assertEqual((cm.exception.line, cm.exception.col), (line, col), code)
            self.assertIn(words, cm.exception.message, code)


class Guards(unittest.TestCase):
    def test_tree_and_positions(self):
        g = guard("a && !b.c || after(250ms)")
        self.assertIsInstance(g, S.Binary)
        self.assertEqual(g.op, "||")
        self.assertEqual(g.left.op, "&&")
        self.assertEqual(g.left.right, S.Unary((1, 6), "!", S.Member((1, 7), S.Name((1, 7), ("b",)), "c")))
        self.assertEqual(g.right.pos, (1, 14))
        self.assertEqual(g.right.args[0], S.NumberLit((1, 20), "250ms", "duration", "ms"))

    def test_precedence_is_cxx(self):
        self.assertEqual(S.print_expr(guard("a | b == c")), "a | b == c")
        g = guard("a | b == c")
        self.assertEqual((g.op, g.right.op), ("|", "=="))  # == binds tighter than | (unlike Python)
        g = guard("a - b - c")
        self.assertEqual((g.op, g.left.op), ("-", "-"))  # left-associative
        g = guard("a ? b : c ? d : e")
        self.assertIsInstance(g.otherwise, S.Conditional)  # right-associative

    def test_alternative_tokens_read_as_operators(self):
        self.assertEqual(S.print_expr(guard("not a and b or c")), "!a && b || c")

    def test_printing_keeps_parentheses_and_separates_signs(self):
        self.assertEqual(S.print_expr(guard("( a+b )*c")), "(a + b) * c")
        self.assertEqual(S.print_expr(guard("- -x")), "- -x")
        self.assertEqual(S.print_expr(guard("static_cast<unsigned long>(x)>=ringlet::wb::K::kA")),
                         "static_cast<unsigned long>(x) >= ringlet::wb::K::kA")

    def test_refused_guards(self):
        for text, col, words in [
            ("x) || (true", 2, "unmatched ')'"),
            ("[&]{ return true; }()", 1, "lambdas"),
            ("x = 1", 3, "side effects: '='"),
            ("x += 1", 3, "side effects: '+='"),
            ("x++ > 1", 2, "side effects: '++'"),
            ("--x", 1, "side effects: '--'"),
            ("f(x)", 1, "calls 'f()'"),
            ("a.b(x)", 1, "calls 'a.b()'"),
            ("(f)(x)", 1, "calls '...()'"),
            ("a, b", 2, "comma operator"),
            ("after(1, 2)", 1, "one argument"),
            ("new int", 1, "side effects: 'new'"),
            ("sizeof(x)", 1, "'sizeof' is not allowed"),
            ("p->x", 2, "'->'"),
            ("*p", 1, "dereference"),
            ('s == "x"', 6, "string"),
            ("a &&", 5, "ends early"),
            ("(a", 3, "ends early"),
            ("1x2", 1, "malformed number"),
            ("09", 1, "malformed number"),
            ("(" * 70 + "a" + ")" * 70, 65, "nested too deeply"),
            ("!" * 70 + "a", 64, "nested too deeply"),
            ("+".join(["a"] * 300), 256, "too long"),
        ]:
            got_col, message = guard_error(text)
            self.assertIn(words, message, text)
            self.assertEqual(got_col, col, text)


class Types(unittest.TestCase):
    def parse(self, text, allow_ref=True):
        return parse_type(lex_line(text, 1), (1, len(text) + 1), allow_ref)

    def test_allowed_types_print_canonically(self):
        for text, printed in [("unsigned  long", "unsigned long"), ("std::int32_t", "std::int32_t"),
                              ("const ns::Thing &", "const ns::Thing&"),
                              ("std::array<std::array<double,2>,3>", "std::array<std::array<double, 2>, 3>"),
                              ("::ringlet::wb::Pose", "::ringlet::wb::Pose")]:
            self.assertEqual(S.print_type(self.parse(text)), printed)

    def test_refused_types(self):
        for text, words, allow_ref in [("int; void f() {} int", "unexpected ';'", True),
                                       ("Foo", "unknown type 'Foo'", True), ("int*", "pointer", True),
                                       ("double&", "only allowed for a parameter", False),
                                       ("std::vector<int>", "only supported for std::array", True),
                                       ("long short", "not a fundamental type", True),
                                       ("ns::class", "keyword", True), ("const int", "const T&", True),
                                       ("std::array<int, 1.5>", "integer", True)]:
            with self.assertRaises(SourceError, msg=text) as cm:
                self.parse(text, allow_ref)
            self.assertIn(words, cm.exception.message, text)

    def test_initial_values(self):
        v = parse_initial_value(lex_line("{1, -2, ns::k}", 1), (1, 15))
        self.assertEqual(S.print_expr(v), "{1, -2, ns::k}")
        with self.assertRaises(SourceError):
            parse_initial_value(lex_line("0; evil()", 1), (1, 10))


class Files(unittest.TestCase):
    """The process as the build runs it: errors are one line, never a traceback."""

    def run_llfsmc(self, *args):
        r = subprocess.run([sys.executable, support.LLFSMC, *args], capture_output=True, text=True)
        self.assertNotIn("Traceback", r.stderr)
        return r.returncode, r.stderr.strip()

    def test_missing_model_directory_and_fifo(self):
        with tempfile.TemporaryDirectory() as tmp:
            fifo = os.path.join(tmp, "fifo.machine")
            os.mkfifo(fifo)
            for path, words in [(os.path.join(tmp, "none.machine"), "No such file"), (tmp, "is a directory"),
                                (fifo, "not a regular file")]:
                status, err = self.run_llfsmc(path)
                self.assertEqual(status, 1)
                self.assertEqual(err, f"{path}: error: cannot read model: " + err.split("cannot read model: ")[1])
                self.assertIn(words, err)

    def test_unwritable_output(self):
        with tempfile.TemporaryDirectory() as tmp:
            blocker = os.path.join(tmp, "file")
            open(blocker, "w").close()
            out = os.path.join(blocker, "sub", "m.hpp")  # a regular file where a directory must be
            model = os.path.join(support.ROOT, "tests", "behaviour", "models", "timer.machine")
            status, err = self.run_llfsmc(model, "--hpp", out)
            self.assertEqual(status, 1)
            self.assertTrue(err.startswith(f"{out}: error: cannot write output: "), err)
            self.assertEqual(os.listdir(tmp), ["file"])  # nothing left behind

    def test_invalid_utf8_names_the_position(self):
        status, err, path, _ = support.compile_bytes(b"machine M\n\nstate A initial \xc3\x28\nend\n")
        self.assertEqual(status, 1)
        self.assertEqual(err, [f"{path}:3:17: error: invalid UTF-8 (byte 0xc3): a model is UTF-8 text"])

    def test_options_reaching_the_cpp_are_checked(self):
        model = os.path.join(support.ROOT, "tests", "behaviour", "models", "timer.machine")
        status, err = self.run_llfsmc(model, "--namespace", "a::b; int x")
        self.assertEqual(status, 1)
        self.assertIn("--namespace", err)
        status, err = self.run_llfsmc(model, "--include-dir", 'x"y')
        self.assertEqual(status, 1)
        self.assertIn("--include-dir", err)

    def test_missing_schema(self):
        model = os.path.join(support.ROOT, "tests", "behaviour", "models", "timer.machine")
        status, err = self.run_llfsmc(model, "--schema", "/nonexistent/schema.def")
        self.assertEqual((status, err), (1, "/nonexistent/schema.def: error: cannot read whiteboard schema: "
                                            "No such file or directory"))


if __name__ == "__main__":
    unittest.main()
