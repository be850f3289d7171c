"""Error collection and the one error format: `FILE:LINE:COL: error: message` (or `FILE: error:
message` when no position applies, e.g. an unreadable file)."""


class Abort(Exception):
    """Stops the compilation of a model after an error it cannot recover from (already recorded)."""


class SourceError(Exception):
    """An error at a position in a text (lexer and parser); line and col are 1-based."""

    def __init__(self, line, col, message):
        super().__init__(message)
        self.line, self.col, self.message = line, col, message


class Diagnostics:
    def __init__(self, path):
        self.path = path
        self.items = []  # (line, col, message)

    def error(self, line, col, message):
        item = (line, col, message)
        if item not in self.items:
            self.items.append(item)

    def add(self, exc):
        self.error(exc.line, exc.col, exc.message)

    def __bool__(self):
        return bool(self.items)

    def lines(self):
        return [f"{self.path}:{line}:{col}: error: {message}"
                for line, col, message in sorted(self.items, key=lambda i: (i[0], i[1]))]


def file_error(path, message):
    """A whole-file error line (nothing to point at inside the file)."""
    return f"{path}: error: {message}"
