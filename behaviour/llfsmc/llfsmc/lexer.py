"""Tokens: of one model line (declarations, transitions: guards, types, initial values) and of a
C++ action block (to find its closing brace and the identifiers it mentions).

Both are hand-written scanners over characters: string and character literals, comments and
digit separators are recognised as C++ recognises them, so that none of them can hide a brace,
a '#' or the end of a guard.
"""

from .diagnostics import SourceError

# C++ punctuators, longest first (so that '<<=' is not read as '<<' '=').
PUNCTUATORS = sorted(
    ["<=>", "->*", "<<=", ">>=", "...", "::", "->", ".*", "++", "--", "==", "!=", "<=", ">=", "&&",
     "||", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<", ">>", "##", "<:", ":>", "<%", "%>",
     "%:", "{", "}", "[", "]", "(", ")", "<", ">", ";", ":", ",", ".", "?", "!", "~", "+", "-", "*",
     "/", "%", "^", "&", "|", "=", "#"],
    key=len, reverse=True)
STRING_PREFIXES = ("u8R", "uR", "UR", "LR", "R", "u8", "u", "U", "L")
CHAR_PREFIXES = ("u8", "u", "U", "L")


class Token:
    __slots__ = ("kind", "text", "line", "col")

    def __init__(self, kind, text, line, col):
        self.kind, self.text, self.line, self.col = kind, text, line, col  # kind: ident number string char op

    def is_op(self, *texts):
        return self.kind == "op" and self.text in texts

    def is_word(self, *texts):
        return self.kind == "ident" and self.text in texts

    def __repr__(self):
        return f"Token({self.kind}, {self.text!r}, {self.line}:{self.col})"


def _ident_start(c):
    return c.isascii() and (c.isalpha() or c == "_")


def _ident_char(c):
    return c.isascii() and (c.isalnum() or c == "_")


def _number_end(text, i):
    """End of the C++ preprocessing number starting at i (digits, '.', suffixes, exponents with
    a sign, and ' digit separators)."""
    n = len(text)
    j = i + 1
    while j < n:
        c = text[j]
        if c in "+-" and text[j - 1] in "eEpP":
            j += 1
        elif _ident_char(c) or c == ".":
            j += 1
        elif c == "'" and j + 1 < n and _ident_char(text[j + 1]):
            j += 2
        else:
            break
    return j


def _quoted_end(text, i, quote, what, pos):
    """Index just past the closing quote of the literal opening at i; escapes skip a character.
    A line end or the end of the text before the closing quote is an error."""
    j, n = i + 1, len(text)
    while j < n and text[j] != quote:
        if text[j] == "\n":
            break
        j += 2 if text[j] == "\\" else 1
    if j >= n or text[j] != quote:
        raise SourceError(*pos(i), f"unterminated {what} literal")
    return j + 1


def lex_line(text, line, first_col=1):
    """Tokens of one line of the model outside code blocks. '#' starts a model comment that runs to
    the end of the line; C++ comments are refused here (a guard ends at the end of its line)."""
    out = []
    i, n = 0, len(text)

    def pos(k):
        return line, first_col + k

    while i < n:
        c = text[i]
        if c in " \t\r\f\v":
            i += 1
        elif c == "#":
            break
        elif text.startswith("//", i) or text.startswith("/*", i):
            raise SourceError(*pos(i), "C++ comments are not allowed outside code blocks "
                                       "(a model comment starts with '#' and runs to the end of the line)")
        elif c.isdigit() or (c == "." and i + 1 < n and text[i + 1].isdigit()):
            j = _number_end(text, i)
            out.append(Token("number", text[i:j], *pos(i)))
            i = j
        elif _ident_start(c):
            j = i + 1
            while j < n and _ident_char(text[j]):
                j += 1
            out.append(Token("ident", text[i:j], *pos(i)))
            i = j
        elif c in "\"'":
            j = _quoted_end(text, i, c, "string" if c == '"' else "character", pos)
            out.append(Token("string" if c == '"' else "char", text[i:j], *pos(i)))
            i = j
        else:
            for p in PUNCTUATORS:
                if text.startswith(p, i):
                    out.append(Token("op", p, *pos(i)))
                    i += len(p)
                    break
            else:
                raise SourceError(*pos(i), f"unexpected character {describe_char(c)}")
    return out


def describe_char(c):
    return f"'{c}'" if c.isprintable() and not c.isspace() else f"U+{ord(c):04X}"


class LineMap:
    """Index in the text -> (line, col), both 1-based."""

    def __init__(self, text):
        self.starts = [0]
        for k, c in enumerate(text):
            if c == "\n":
                self.starts.append(k + 1)

    def __call__(self, index):
        lo, hi = 0, len(self.starts) - 1
        while lo < hi:
            mid = (lo + hi + 1) // 2
            if self.starts[mid] <= index:
                lo = mid
            else:
                hi = mid - 1
        return lo + 1, index - self.starts[lo] + 1


def scan_block(text, start, pos):
    """Scans C++ action code from `start` (just after the opening '{') to the brace that closes it.

    Returns (end, tokens): `end` is the index just past the closing '}', or -1 if the text ends
    first; tokens are the code's tokens (comments dropped, the closing brace excluded). Raises
    SourceError for what would make the compiler see a different structure than this scanner
    does: unterminated comments and literals, line continuations, preprocessor directives.
    `pos` maps an index to (line, col).
    """
    tokens = []
    depth = 1
    i, n = start, len(text)
    line_start = True  # only white space since the last line end (a '#' here is a directive)
    while i < n:
        c = text[i]
        if c == "\n":
            line_start = True
            i += 1
            continue
        if c in " \t\r\f\v":
            i += 1
            continue
        if c == "\\":
            j = i + 1
            while j < n and text[j] in " \t\r\f\v":
                j += 1
            if j >= n or text[j] == "\n":
                raise SourceError(*pos(i), "line continuation ('\\' at the end of a line) is not allowed in action code")
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            if text[i:j].rstrip().endswith("\\"):
                raise SourceError(*pos(i), "a '//' comment ending in '\\' would continue on the next line: "
                                           "line continuations are not allowed in action code")
            i = j
            continue
        if text.startswith("/*", i):
            j = text.find("*/", i + 2)
            if j < 0:
                raise SourceError(*pos(i), "unterminated comment ('/*' without '*/')")
            i = j + 2
            continue
        was_line_start, line_start = line_start, False
        if c == "#" or text.startswith("%:", i):
            if was_line_start:
                raise SourceError(*pos(i), "preprocessor directives are not allowed in action code "
                                           "(headers are included with 'include' lines at model level)")
            raise SourceError(*pos(i), "unexpected '#' in action code")
        if _ident_start(c) or not c.isascii():
            j = i + 1
            while j < n and (_ident_char(text[j]) or not text[j].isascii()) and text[j] != "\n":
                j += 1
            word = text[i:j]
            if j < n and text[j] == '"' and word in STRING_PREFIXES:
                i = _raw_string_end(text, j, pos) if word.endswith("R") else _quoted_end(text, j, '"', "string", pos)
                tokens.append(Token("string", text[j - len(word):i], *pos(j - len(word))))
                continue
            if j < n and text[j] == "'" and word in CHAR_PREFIXES:
                i = _quoted_end(text, j, "'", "character", pos)
                tokens.append(Token("char", text[j - len(word):i], *pos(j - len(word))))
                continue
            tokens.append(Token("ident", word, *pos(i)))
            i = j
            continue
        if c.isdigit() or (c == "." and i + 1 < n and text[i + 1].isdigit()):
            j = _number_end(text, i)
            tokens.append(Token("number", text[i:j], *pos(i)))
            i = j
            continue
        if c in "\"'":
            j = _quoted_end(text, i, c, "string" if c == '"' else "character", pos)
            tokens.append(Token("string" if c == '"' else "char", text[i:j], *pos(i)))
            i = j
            continue
        for p in PUNCTUATORS:
            if text.startswith(p, i):
                break
        else:
            p = c
        if p in ("{", "<%"):
            depth += 1
        elif p in ("}", "%>"):
            depth -= 1
            if depth == 0:
                return i + len(p), tokens
        tokens.append(Token("op", p, *pos(i)))
        i += len(p)
    return -1, tokens


def _raw_string_end(text, quote, pos):
    """Index just past the raw string literal R"delim( ... )delim" whose '"' is at `quote`."""
    open_paren = text.find("(", quote + 1, quote + 18)
    delim = text[quote + 1:open_paren] if open_paren >= 0 else None
    if delim is None or any(ch in delim for ch in " ()\\\t\v\f\n"):
        raise SourceError(*pos(quote), "malformed raw string literal delimiter")
    close = text.find(")" + delim + '"', open_paren + 1)
    if close < 0:
        raise SourceError(*pos(quote), "unterminated raw string literal")
    return close + len(delim) + 2


def free_identifiers(tokens):
    """Identifiers not reached through '.', '->' or '::' (member names do not count)."""
    out = []
    for k, t in enumerate(tokens):
        if t.kind != "ident":
            continue
        if k > 0 and tokens[k - 1].is_op(".", "->", "::"):
            continue
        out.append(t.text)
    return out
