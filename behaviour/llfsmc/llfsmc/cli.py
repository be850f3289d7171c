"""llfsmc command line: compiles one LLFSM model (a .machine file) to C++ and a Graphviz diagram.

    llfsmc.py MODEL [--hpp OUT.hpp --cpp OUT.cpp] [--dot OUT.dot] [--schema schema.def]
              [--namespace ringlet::behaviour::machines] [--include-dir ringlet/behaviour/machines]
              [--promela OUT.pml [--ringlets N] [--period-ms P]]
    llfsmc.py SCHEDULE.schedule --promela OUT.pml        (a schedule of machines, schedule_file.py)

--promela also writes OUT.pml.json (state names, inputs, properties: for spin_verify.py).

With no outputs it only checks the model. Every error goes to stderr as
`MODEL:LINE:COL: error: message` (or `FILE: error: message` when there is no position: an
unreadable file, an unwritable output), and the exit status is 1; nothing is written then.
Command-line misuse exits with 2 (argparse). The format is documented in behaviour/README.md.
Standard library only: it runs on the build host, also for cross builds.
"""

import argparse
import os
import sys

from .check import check_model, footprints
from .diagnostics import Abort, Diagnostics, file_error
from .emit_cpp import generate_header, generate_source
from .emit_dot import generate_dot
from .emit_promela import ScheduleEntry, generate_promela, metadata_json
from .schedule_file import parse_schedule
from .model_parser import parse_model
from .names import identifier_problem
from .schema import parse_schema
from .source import MAX_MODEL_BYTES, MAX_SCHEMA_BYTES, FileProblem, read_text, write_text

DEFAULT_SCHEMA = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                               "whiteboard", "include", "ringlet", "whiteboard", "schema.def"))
PATH_CHARS = set("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_./+-")


def argument_parser():
    ap = argparse.ArgumentParser(prog="llfsmc.py", description=__doc__.split("\n")[0])
    ap.add_argument("model")
    ap.add_argument("--hpp")
    ap.add_argument("--cpp")
    ap.add_argument("--dot")
    ap.add_argument("--schema", default=DEFAULT_SCHEMA, help="the whiteboard schema (schema.def)")
    ap.add_argument("--namespace", default="ringlet::behaviour::machines")
    ap.add_argument("--include-dir", default="ringlet/behaviour/machines",
                    help="directory the generated header is included from (include path prefix)")
    ap.add_argument("--promela", help="write a Promela model for spin (behaviour/README.md, Model checking)")
    ap.add_argument("--ringlets", type=int, default=1, help="ringlets per turn of a single machine (--promela)")
    ap.add_argument("--period-ms", type=int, default=10,
                    help="one turn of a single machine in ms (--promela; the firmware's [executive] period)")
    return ap


def option_problems(args):
    """The options end up in the generated C++: they must be names and paths, nothing else."""
    out = []
    parts = args.namespace.split("::")
    if any(identifier_problem(p) for p in parts):
        out.append(file_error("llfsmc", f"--namespace '{args.namespace}' is not a ::-separated list of C++ identifiers"))
    if not args.include_dir or not set(args.include_dir) <= PATH_CHARS or ".." in args.include_dir:
        out.append(file_error("llfsmc", f"--include-dir '{args.include_dir}' must be a relative path of "
                                        "letters, digits and _ . / + -"))
    stem = os.path.splitext(os.path.basename(args.model))[0]
    if args.promela and (args.hpp or args.cpp or args.dot):
        out.append(file_error("llfsmc", "--promela is a run of its own (no --hpp/--cpp/--dot with it)"))
    if not stem or not set(stem) <= PATH_CHARS:
        out.append(file_error(args.model, "the model's file name must be letters, digits and _ . + - "
                                          "(the generated header is named after it)"))
    return out


def load_model(path, schema):
    """(model or None, error lines)."""
    try:
        text = read_text(path, "model", MAX_MODEL_BYTES)
    except FileProblem as p:
        if p.line is not None:
            return None, [f"{path}:{p.line}:{p.col}: error: {p.message}"]
        return None, [file_error(path, p.message)]
    diags = Diagnostics(path)
    try:
        model = parse_model(text, diags)
        check_model(model, schema, diags)
    except Abort:
        pass
    if diags:
        return None, diags.lines()
    model.source_name = os.path.basename(path)
    footprints(model)
    return model, []


def apply_schedule_assumes(sched, entries, schema, diags):
    """A schedule's `assume` lines replace the machines' own for this schedule."""
    from . import syntax as S
    from .model import Assume
    for head, name, values, kind, pos in sched.assumes:
        hit = False
        for e in entries:
            m = e.model
            if kind == "value" and head == m.name and name in m.variables and m.variables[name].kind == "parameter":
                target = S.Name(pos, (name,))
            elif kind == "domain" and head in schema.messages:
                ext = next((v for v in m.variables.values() if v.kind == "external" and v.type == head), None)
                if ext is None:
                    continue
                target = S.Member(pos, S.Name(pos, (ext.name,)), name)
            else:
                continue
            text = S.print_expr(target)
            m.assumes = [a for a in m.assumes if not (a.kind == kind and S.print_expr(a.target) == text)]
            m.assumes.append(Assume(kind, target, values, pos))
            hit = True
        if not hit:
            diags.error(*pos, f"'{head}.{name}' is no parameter of a scheduled machine and no whiteboard "
                              "field one of them reads")


def compile_promela(args, schema):
    """--promela for a model or a schedule: (error lines, {path: text})."""
    sched_diags = Diagnostics(args.model)
    if args.model.endswith(".schedule"):
        try:
            text = read_text(args.model, "schedule", MAX_MODEL_BYTES)
        except FileProblem as p:
            return [file_error(args.model, p.message)], {}
        sched = parse_schedule(text, sched_diags)
        if sched_diags:
            return sched_diags.lines(), {}
        base = os.path.dirname(os.path.abspath(args.model))
        entries, errors = [], []
        for path, n, _pos in sched.machines:
            full = os.path.normpath(os.path.join(base, path))
            model, errs = load_model(full, schema)
            errors += errs
            if model is not None:
                entries.append(ScheduleEntry(model, n, full))
        if errors:
            return errors, {}
        apply_schedule_assumes(sched, entries, schema, sched_diags)
        if sched_diags:
            return sched_diags.lines(), {}
        period, props, own = sched.period_ms, sched.properties, False
    else:
        model, errors = load_model(args.model, schema)
        if errors:
            return errors, {}
        entries = [ScheduleEntry(model, args.ringlets, args.model)]
        period, props, own = args.period_ms, [], True
    per_file = {e.path: Diagnostics(e.path) for e in entries}
    text, meta = generate_promela(entries, schema, period, props,
                                  lambda e: sched_diags if e is None else per_file[e.path], own)
    lines = sched_diags.lines() + [line for d in per_file.values() for line in d.lines()]
    if lines:
        return lines, {}
    return [], {args.promela: text, args.promela + ".json": metadata_json(meta)}


def compile_model(args):
    """Returns (error lines, {output path: text})."""
    try:
        schema = parse_schema(read_text(args.schema, "whiteboard schema", MAX_SCHEMA_BYTES))
    except FileProblem as p:
        return [file_error(args.schema, p.message)], {}
    except ValueError as exc:
        line, message = exc.args
        return [f"{args.schema}:{line}:1: error: {message}"], {}
    if args.promela:
        return compile_promela(args, schema)
    try:
        text = read_text(args.model, "model", MAX_MODEL_BYTES)
    except FileProblem as p:
        if p.line is not None:
            return [f"{args.model}:{p.line}:{p.col}: error: {p.message}"], {}
        return [file_error(args.model, p.message)], {}
    diags = Diagnostics(args.model)
    try:
        model = parse_model(text, diags)
        check_model(model, schema, diags)
    except Abort:
        pass
    if diags:
        return diags.lines(), {}
    model.source_name = os.path.basename(args.model)
    footprints(model)
    stem = os.path.splitext(os.path.basename(args.model))[0]
    include_path = f"{args.include_dir}/{stem}.hpp"
    outputs = {}
    if args.hpp:
        outputs[args.hpp] = generate_header(model, args.namespace, include_path)
    if args.cpp:
        outputs[args.cpp] = generate_source(model, args.namespace, include_path, os.path.abspath(args.model),
                                            os.path.abspath(args.cpp))
    if args.dot:
        outputs[args.dot] = generate_dot(model)
    return [], outputs


def run(argv, stderr):
    """The compiler without the last-resort guard (tests call this, so a bug shows as a traceback)."""
    args = argument_parser().parse_args(argv)
    problems = option_problems(args)
    if problems:
        stderr.write("\n".join(problems) + "\n")
        return 1
    errors, outputs = compile_model(args)
    if errors:
        stderr.write("\n".join(errors) + "\n")
        return 1
    for path, text in outputs.items():
        try:
            write_text(path, text)
        except FileProblem as p:
            stderr.write(file_error(path, p.message) + "\n")
            return 1
    return 0


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    try:
        return run(argv, sys.stderr)
    except KeyboardInterrupt:
        return 130
    except Exception as exc:  # a bug in llfsmc: still one line naming the input, never a traceback
        model = next((a for a in argv if not a.startswith("-")), "llfsmc")
        sys.stderr.write(file_error(model, f"internal error in llfsmc ({type(exc).__name__}: {exc}); "
                                           "please report it with this model") + "\n")
        return 1
