"""Shared by the llfsmc Python tests: the compiler package on the path, the repository's models,
and running the compiler in-process on a text."""

import io
import os
import sys
import tempfile

sys.dont_write_bytecode = True
ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
LLFSMC_DIR = os.path.join(ROOT, "behaviour", "llfsmc")
LLFSMC = os.path.join(LLFSMC_DIR, "llfsmc.py")
SCHEMA = os.path.join(ROOT, "whiteboard", "include", "ringlet", "whiteboard", "schema.def")
sys.path.insert(0, LLFSMC_DIR)

from llfsmc import cli  # noqa: E402


def model_paths():
    """The shipped machines and the good test models."""
    out = []
    for d in (os.path.join(ROOT, "behaviour", "machines"), os.path.join(ROOT, "tests", "behaviour", "models")):
        out += sorted(os.path.join(d, f) for f in os.listdir(d) if f.endswith(".machine"))
    return out


def compile_bytes(data, outputs=True, name="model.machine"):
    """Runs the compiler on `data` (bytes) in a fresh directory: (exit status, stderr lines, path)."""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, name)
        with open(path, "wb") as f:
            f.write(data)
        argv = [path, "--schema", SCHEMA]
        if outputs:
            argv += ["--hpp", os.path.join(tmp, "out", "m.hpp"), "--cpp", os.path.join(tmp, "out", "m.cpp"),
                     "--dot", os.path.join(tmp, "out", "m.dot")]
        err = io.StringIO()
        status = cli.run(argv, err)
        produced = all(os.path.isfile(os.path.join(tmp, "out", n)) for n in ("m.hpp", "m.cpp", "m.dot"))
        return status, err.getvalue().splitlines(), path, produced


def error_shape_problem(line, path, line_count):
    """None if `line` is `PATH:LINE:COL: error: message` with LINE inside the file (or one past
    its end) and COL >= 1, or `PATH: error: message`; else what is wrong."""
    if not line.startswith(path + ":"):
        return "does not start with the model path"
    rest = line[len(path) + 1:]
    if rest.startswith(" error: ") and len(rest) > len(" error: "):
        return None
    parts = rest.split(":", 2)
    if len(parts) != 3 or not parts[0].isdigit() or not parts[1].isdigit():
        return "no LINE:COL"
    if not 1 <= int(parts[0]) <= line_count + 1 or int(parts[1]) < 1:
        return f"position {parts[0]}:{parts[1]} outside the file ({line_count} lines)"
    if not parts[2].startswith(" error: ") or len(parts[2]) <= len(" error: "):
        return "no ' error: message'"
    if "internal error" in parts[2]:
        return "internal error"
    return None
