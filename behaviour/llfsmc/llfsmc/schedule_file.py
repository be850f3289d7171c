"""The schedule format (`*.schedule`): what the firmware's fsm task runs, for the model checker.

    # comment
    period 10ms                              # one turn of the executive ([executive] period_us)
    machine mission.machine                  # in schedule order; path relative to this file
    machine safety.machine ringlets 2        # ringlets per turn (default 1)
    ltl stop_stands: [] (!at(Safety, Clear) -> MotionCommand.stop)
    assert name: expression                  # checked at the end of every turn
    assume Safety.hold_ms = 30               # a machine parameter's value for this schedule
    assume LaserSummary.nearest_range in {0.3, 1.0}   # an input's domain for this schedule

The `assume` lines override the machines' own (a coarser abstraction or a shorter time keeps the
product of the machines small; say next to them why the properties do not depend on it).

In a schedule's properties a whiteboard field is `Type.field` and a machine's variable
`Machine.variable`; states are `at(Machine, State)`.
"""

from .diagnostics import SourceError
from .expr_parser import parse_initial_value
from .lexer import lex_line
from .model import Property
from .vexpr import parse_ltl


class Schedule:
    def __init__(self):
        self.period_ms = None
        self.machines = []  # (path, ringlets, (line, col))
        self.properties = []
        self.assumes = []  # (Machine or Type, name, tree, kind "value"/"domain", pos)


def parse_schedule(text, diags):
    sched = Schedule()
    for lineno, raw in enumerate(text.split("\n"), 1):
        try:
            toks = lex_line(raw, lineno)
            if not toks:
                continue
            first = toks[0]
            if first.is_word("period"):
                if len(toks) != 2 or toks[1].kind != "number" or not toks[1].text.endswith("ms"):
                    raise SourceError(first.line, first.col, "expected 'period <N>ms'")
                sched.period_ms = int(toks[1].text[:-2])
                if sched.period_ms <= 0:
                    raise SourceError(toks[1].line, toks[1].col, "the period must be positive")
            elif first.is_word("machine"):
                # the path is the rest of the line up to 'ringlets' (paths are not tokens)
                body = raw.split("#", 1)[0].split()
                if len(body) not in (2, 4) or (len(body) == 4 and (body[2] != "ringlets" or not body[3].isdigit())):
                    raise SourceError(first.line, first.col, "expected 'machine <file.machine> [ringlets N]'")
                n = int(body[3]) if len(body) == 4 else 1
                if n < 1:
                    raise SourceError(first.line, first.col, "ringlets per turn must be >= 1")
                sched.machines.append((body[1], n, (first.line, first.col)))
            elif first.is_word("assume"):
                ok = len(toks) >= 6 and toks[1].kind == "ident" and toks[2].is_op(".") and toks[3].kind == "ident" \
                    and (toks[4].is_op("=") or toks[4].is_word("in"))
                if not ok:
                    raise SourceError(first.line, first.col,
                                      "expected 'assume Machine.parameter = v' or 'assume Type.field in {...}'")
                last = toks[-1]
                values = parse_initial_value(toks[5:], (last.line, last.col + len(last.text)))
                sched.assumes.append((toks[1].text, toks[3].text, values,
                                      "value" if toks[4].is_op("=") else "domain", (first.line, first.col)))
            elif first.is_word("ltl", "assert"):
                if len(toks) < 4 or toks[1].kind != "ident" or not toks[2].is_op(":"):
                    raise SourceError(first.line, first.col, f"expected '{first.text} <name>: <formula>'")
                if any(p.name == toks[1].text for p in sched.properties):
                    raise SourceError(toks[1].line, toks[1].col, f"duplicate property '{toks[1].text}'")
                last = toks[-1]
                tree = parse_ltl(toks[3:], (last.line, last.col + len(last.text)))
                sched.properties.append(Property(first.text, toks[1].text, tree, (first.line, first.col)))
            else:
                raise SourceError(first.line, first.col, f"unknown keyword '{first.text}' "
                                                         "(expected period, machine, ltl or assert)")
        except SourceError as e:
            diags.add(e)
    if sched.period_ms is None:
        diags.error(1, 1, "missing 'period <N>ms'")
    if not sched.machines:
        diags.error(1, 1, "a schedule needs at least one 'machine' line")
    return sched
