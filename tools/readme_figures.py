#!/usr/bin/env python3
"""The README's figures: check the deterministic ones against a fresh run, fill in the measured ones.

README.md marks its figures with HTML comments (invisible when rendered):

  <!--fig:KEY-->VALUE<!--/fig-->           a deterministic figure (hash, goals, distance, frame
                                           counts...): `check` compares VALUE with a fresh run.
                                           The README is where the expected value lives.
  <!--results:KEY-->VALUE<!--/results-->   a measured figure (host time, CPU p99...): written by
                                           `tools/ringlet results` from its run, never checked.
  <!--results-block:CONFIG.output-->       on lines of their own, around a fenced block: the
  ...                                      configuration's console output, written by
  <!--/results-block-->                    `tools/ringlet results`; `check` compares its
                                           deterministic lines with the run (measured columns,
                                           host time and progress lines are masked).

KEY is SOURCE.FIGURE. SOURCE is the stem of a shipped configuration (firmware/config/SOURCE.toml),
realtime_STEM (a few seconds of it on the real clock), vision_eval_SEED (the vision evaluation;
these two are run by `tools/ringlet results` only) or plan_bench_MAP (`ringlet-plan-bench replan`
on planning/maps/MAP.map with its .scen: expansions are deterministic, so `check` runs it too). A number is
compared at the precision it is written with: "24.2" matches 24.16, "89" matches 89.3. A value
may be a code span (<!--fig:KEY-->`aa41...`<!--/fig-->; inside the backticks a comment would show).

Used by the CTest ReadmeFigures (`check`, running the firmware in lockstep for every configuration
the README names) and imported by tools/results.py.
"""

import argparse
import json
import os
import re
import stat
import subprocess
import sys
from pathlib import Path

MAX_README_BYTES = 4 * 1024 * 1024
INLINE = re.compile(r"<!--(fig|results):([A-Za-z0-9_.\-]+)-->(.*?)<!--/\1-->")
ANY_MARKER = re.compile(r"<!--/?(fig|results|results-block)\b")
BLOCK_BEGIN = re.compile(r"^\s*<!--results-block:([A-Za-z0-9_\-]+)\.output-->\s*$")
BLOCK_END = re.compile(r"^\s*<!--/results-block-->\s*$")
NUMBER = re.compile(r"^-?\d+(\.(\d+))?$")


class BadInput(Exception):
    """A problem with the README or the arguments: exit 2."""


# ---------------------------------------------------------------------------------------------
# Figures from the tools' JSON reports
# ---------------------------------------------------------------------------------------------

def firmware_figures(report):
    """(deterministic, measured) figures of one `ringlet --report` JSON, keyed by FIGURE."""
    mission, timing, schedule = report["mission"], report["timing"], report["schedule"]
    tasks = timing["tasks"]
    det = {
        "goals": f'{mission["goals_reached"]}/{mission["goal_count"]}',
        "complete": "yes" if mission["complete"] else "no",
        "mission_s": mission["mission_seconds"],
        "distance_m": mission["distance_m"],
        "collisions": mission["collisions"],
        "trajectory_hash": mission["trajectory_hash"],
        "run_hash": mission["run_hash"],
        "seed": mission["seed"],
        "frames": timing["frames"]["executed"],
        "overruns": sum(t["overruns"] for t in tasks),
        "skipped": sum(t["skipped"] for t in tasks),
        "degraded_runs": sum(t["degraded_runs"] for t in tasks),
        "fsm_status_seen": mission["fsm_status_seen"],
    }
    frames = timing["frames"]
    meas = {
        "host_s": mission["host_seconds"],
        "measured_overruns": sum(t["measured_overruns"] for t in tasks),
        # On the schedule clock: zero in lockstep by construction, measured on the real clock.
        "frame_overruns": frames["frame_overruns"],
        "slips": frames["slips"],
        "wake_p99_us": frames["wake_latency"]["p99_us"],
        "busy_p99_us": frames["busy"]["p99_us"],
    }
    vision = mission.get("vision")
    if vision:
        frames = vision["frames"]
        share = (lambda n: 100.0 * n / frames) if frames else (lambda n: 0.0)
        det.update({
            "vision.frames": frames,
            "vision.lines_pct": share(vision["with_lines"]),
            "vision.lines_per_frame": vision["lines"] / frames if frames else 0.0,
            "vision.ball_pct": share(vision["with_ball"]),
            "vision.cut": vision["cut"],
            "vision.lines_cut": vision["lines_cut"],
            "vision.robots": vision["robots"],
            "vision.degraded": vision["degraded"],
            "vision.missed": vision["missed_frames"],
        })
    head = mission.get("head_tracking")
    if head and head["frames"] > 0:
        det.update({
            "head.pct": 100.0 * head["on_target_share"],
            "head.frames": head["frames"],
            # libm (atan2): the same on every x86-64 run; may differ in the last bits on aarch64.
            "head.mean_error_deg": head["mean_error_deg"],
        })
    for t in tasks:
        p = f'task.{t["name"]}.'
        det.update({
            p + "runs": t["runs"],
            p + "budget_us": t["budget_us"],
            p + "budget_ms": t["budget_us"] / 1000.0,
            p + "overruns": t["overruns"],
            p + "skipped": t["skipped"],
            p + "model_p99_us": t["model"]["p99_us"],
            p + "model_p99_ms": t["model"]["p99_us"] / 1000.0,
        })
        meas.update({
            p + "cpu_p99_us": t["cpu"]["p99_us"],
            p + "cpu_p99_ms": t["cpu"]["p99_us"] / 1000.0,
            p + "cpu_p99_pct_of_budget": 100.0 * t["cpu"]["p99_us"] / t["budget_us"],
            p + "wall_p99_us": t["wall"]["p99_us"],
            p + "measured_overruns": t["measured_overruns"],
        })
    ringlets = 0
    weighted = 0.0
    for m in schedule["machines"]:
        det[f'machine.{m["name"]}.ringlets'] = m["ringlets"]
        det[f'machine.{m["name"]}.state'] = m["final_state"]
        ringlets += m["samples"]
        weighted += m["mean_us"] * m["samples"]
    meas["ringlet_avg_us"] = weighted / ringlets if ringlets else 0.0
    return det, meas


def eval_figures(report):
    """(deterministic, measured) figures of one `ringlet-vision-eval --json` report."""
    det = {"frames": report["report_frames"], "tune_frames": report["tune_frames"]}
    meas = {"speed_ratio": report["speed_ratio"]}
    for key, d in report["detectors"].items():
        det.update({f"{key}.f1": d["f1"], f"{key}.precision": d["precision"], f"{key}.recall": d["recall"],
                    f"{key}.detections": d["detections_scored"], f"{key}.recalled": d["recalled"],
                    f"{key}.truths": d["truths"]})
        meas.update({f"{key}.median_ms": d["time_ms"]["median"], f"{key}.p99_ms": d["time_ms"]["p99"]})
    return det, meas


def is_eval_source(source):
    return source.startswith("vision_eval_")


PLAN_PREFIX = "plan_bench_"


def is_plan_source(source):
    return source.startswith(PLAN_PREFIX)


def plan_figures(report):
    """(deterministic, measured) figures of one `ringlet-plan-bench replan --json` report."""
    t = report["totals"]
    det = {k: t[k] for k in ("problems", "reached", "replans", "dstar_lite_expansions", "astar_expansions",
                             "expansion_ratio")}
    meas = {k: t[k] for k in ("dstar_lite_seconds", "astar_seconds", "time_ratio")}
    return det, meas


def run_plan_bench(bench, maps_dir, source, report, svg=None):
    """`ringlet-plan-bench replan` on the map a plan_bench_MAP source names: (exit code, report
    JSON or None, the finished process, the command)."""
    m = source[len(PLAN_PREFIX):]
    cmd = [str(bench), "replan", str(Path(maps_dir) / f"{m}.map"), str(Path(maps_dir) / f"{m}.map.scen"),
           "--json", str(report)]
    if svg:
        cmd += ["--svg", str(svg)]
    if os.path.exists(report):
        os.remove(report)
    p = subprocess.run(cmd, capture_output=True, text=True)
    data = None
    if p.returncode == 0 and os.path.exists(report):
        with open(report, encoding="utf-8") as f:
            data = json.load(f)
    return p.returncode, data, p, cmd


# ---------------------------------------------------------------------------------------------
# The README's markers
# ---------------------------------------------------------------------------------------------

def read_readme(path):
    """The README's text; refuses what is not a regular file of bounded size (exit 2)."""
    try:
        st = os.stat(path)
    except OSError as e:
        raise BadInput(f"{path}: cannot read the README: {e.strerror}") from None
    if not stat.S_ISREG(st.st_mode):
        raise BadInput(f"{path}: cannot read the README: not a regular file")
    if st.st_size > MAX_README_BYTES:
        raise BadInput(f"{path}: cannot read the README: {st.st_size} bytes, more than {MAX_README_BYTES}")
    try:
        return Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as e:
        raise BadInput(f"{path}: cannot read the README: {e}") from None


class Marker:
    def __init__(self, kind, key, value, line, start, end):
        self.kind, self.key, self.value, self.line = kind, key, value, line
        self.start, self.end = start, end  # offsets of VALUE in the whole text
        self.source, _, self.figure = key.partition(".")


class Block:
    def __init__(self, source, first_line, body_start, body_end, lines):
        self.source = source
        self.first_line = first_line        # 1-based line of the begin marker
        self.body_start, self.body_end = body_start, body_end  # line indexes (0-based) of the body
        self.lines = lines                  # the body without its fences: (line number, text)


def parse(text, name):
    """Every marker of the README: (inline markers, blocks). Malformed markers are bad input."""
    inline, blocks, problems = [], [], []
    lines = text.split("\n")
    offset = 0
    open_block = None
    for i, line in enumerate(lines):
        n = i + 1
        if BLOCK_BEGIN.match(line):
            if open_block is not None:
                problems.append(f"{name}:{n}: results-block opened again before line {open_block[1]}'s was closed")
            open_block = (BLOCK_BEGIN.match(line).group(1), n, i)
        elif BLOCK_END.match(line):
            if open_block is None:
                problems.append(f"{name}:{n}: <!--/results-block--> without a block begun before it")
            else:
                blocks.append(_block(lines, open_block, i, name, problems))
                open_block = None
        else:
            covered = []
            for m in INLINE.finditer(line):
                if "<!--" in m.group(3):
                    problems.append(f"{name}:{n}: marker {m.group(2)} holds another marker")
                    continue
                key = m.group(2)
                if "." not in key:
                    problems.append(f"{name}:{n}: marker key '{key}' must be SOURCE.FIGURE")
                    continue
                start, end = m.start(3), m.end(3)
                value = m.group(3)
                # A value in a code span (`aa41...`): the marker stays outside the backticks, where
                # Markdown hides it; the figure is what is inside them.
                if len(value) >= 2 and value[0] == "`" and value[-1] == "`":
                    value, start, end = value[1:-1], start + 1, end - 1
                inline.append(Marker(m.group(1), key, value, n, offset + start, offset + end))
                covered.append((m.start(), m.end()))
            rest = "".join(c for j, c in enumerate(line) if not any(a <= j < b for a, b in covered))
            if ANY_MARKER.search(rest):
                problems.append(f"{name}:{n}: unmatched or malformed figure marker: {line.strip()[:120]}")
        offset += len(line) + 1
    if open_block is not None:
        problems.append(f"{name}:{open_block[1]}: results-block {open_block[0]} is never closed")
    if problems:
        raise BadInput("\n".join(problems))
    return inline, blocks


def _block(lines, opened, end_index, name, problems):
    source, first_line, begin_index = opened
    body = list(range(begin_index + 1, end_index))
    fenced = [i for i in body if lines[i].strip().startswith("```")]
    if len(fenced) != 2 or fenced[0] != body[0] or fenced[1] != body[-1]:
        problems.append(f"{name}:{first_line}: results-block {source} must hold exactly one fenced block (```)")
        return Block(source, first_line, begin_index + 1, end_index, [])
    return Block(source, first_line, begin_index + 1, end_index,
                 [(i + 1, lines[i]) for i in range(fenced[0] + 1, fenced[1])])


# ---------------------------------------------------------------------------------------------
# Comparing and formatting
# ---------------------------------------------------------------------------------------------

def format_like(value, written):
    """VALUE as the README writes it: a number at the precision of WRITTEN, text as it is."""
    if isinstance(value, str):
        return value
    m = NUMBER.match(written.strip())
    if not m:
        return None
    decimals = len(m.group(2)) if m.group(2) else 0
    if decimals == 0:
        return str(int(round(value))) if isinstance(value, float) else str(value)
    return f"{value:.{decimals}f}"


# What differs between the two inline marker kinds: which of a source's (deterministic, measured)
# figures the marker names, what such a figure is called, the hint for a figure of the other kind,
# and how a value that is not a plain number is reported ({run} is the run's value).
MARKER_KINDS = {
    "fig": (0, "deterministic", "a measured figure: mark it <!--results:...-->",
            "is not a plain number (the run gives {run})"),
    "results": (1, "measured", "a deterministic figure: mark it <!--fig:...-->",
                "is not a plain number to replace"),
}


def stated_figures(markers, kind, figures, readme_name):
    """The KIND markers ("fig" or "results") whose source is in FIGURES ({source: (det, meas)}), in
    README order, each as (marker, the run's figure written at the marker's precision, None), or as
    (marker, None, problem) when the source has no such figure or the marker's value is not a plain
    number. One place for both kinds, so `check` and `results` read the markers alike."""
    index, called, other_hint, not_number = MARKER_KINDS[kind]
    for mk in markers:
        if mk.kind != kind or mk.source not in figures:
            continue
        own, other = figures[mk.source][index], figures[mk.source][1 - index]
        if mk.figure not in own:
            hint = f" ({other_hint})" if mk.figure in other else f" (known: {', '.join(sorted(own))})"
            yield mk, None, f"{readme_name}:{mk.line}: {mk.key}: no such {called} figure{hint}"
            continue
        written = format_like(own[mk.figure], mk.value)
        if written is None:
            yield mk, None, (f"{readme_name}:{mk.line}: {mk.key}: '{mk.value}' "
                             + not_number.format(run=own[mk.figure]))
            continue
        yield mk, written, None


def check_inline(markers, figures, readme_name):
    """Problems of the fig markers whose source is in FIGURES ({source: (det, meas)})."""
    problems = []
    for mk, want, problem in stated_figures(markers, "fig", figures, readme_name):
        if problem is not None:
            problems.append(problem)
        elif want != mk.value.strip():
            problems.append(f"{readme_name}:{mk.line}: {mk.key}: README says '{mk.value.strip()}', "
                            f"the run gives '{want}'")
    return problems


def console_excerpt(stdout, stderr):
    """What the README shows of a run: the state changes and progress lines (stderr), less the
    machines too chatty to print them all, then the summary, timing table and schedule (stdout)."""
    err = stderr.splitlines()
    chatty = {m.group(1) for m in (re.match(r"ringlet: fsm (\S+): further changes not shown", l) for l in err) if m}
    kept = [l for l in err if not any(l.startswith(f"ringlet: fsm {c}:") for c in chatty)]
    out = stdout.splitlines()
    start = next((i for i, l in enumerate(out) if l.startswith("MISSION ")), None)
    if start is None:
        return kept
    end = next((i for i, l in enumerate(out) if i > start and l.startswith("report:")), len(out))
    tail = out[start:end]
    while tail and not tail[-1].strip():
        tail.pop()
    return kept + [""] + tail


TASK_ROW = re.compile(r"^\d+\s+\S+\s+[\d.]+Hz\s")
SCHEDULE_ROW = re.compile(r"^\d+\s+\S+\s+\d+\s+\d+\s+[\d.]+\s+[\d.]+\s+\S+\s*$")


def mask(line):
    """LINE with what the host measures replaced by '*'; None for a line not compared at all."""
    if line.startswith("ringlet: running:"):
        return None  # progress, printed on the host's clock
    line = re.sub(r"[\d.]+ s of host time", "* s of host time", line)
    cols = line.split()
    if TASK_ROW.match(line) and len(cols) == 17:
        # #, TASK, RATE, PH, BUDGET, POLICY, RUNS, MIN, AVG, P99, MAX, CPU-P99, MODEL-P99, OVR, MEAS-OVR, SKIP, SHARE
        for i in (7, 8, 9, 10, 11, 14, 16):
            cols[i] = "*"
        return " ".join(cols)
    if SCHEDULE_ROW.match(line):
        # #, MACHINE, PER-TURN, RINGLETS, AVG, MAX, FINAL STATE
        cols[4] = cols[5] = "*"
        return " ".join(cols)
    return " ".join(cols)


def check_block(block, excerpt, readme_name):
    """Problems of one results-block against the run's console excerpt (first difference only)."""
    have = [(n, l, mask(l)) for n, l in block.lines]
    have = [h for h in have if h[2] is not None]
    want = [(l, mask(l)) for l in excerpt]
    want = [w for w in want if w[1] is not None]
    for k, (h, w) in enumerate(zip(have, want)):
        if h[2] != w[1]:
            return [f"{readme_name}:{h[0]}: {block.source} output differs from the run "
                    f"(measured columns masked):\n    README: {h[1]}\n    run:    {w[0]}"]
    if len(have) != len(want):
        where = have[len(want)][0] if len(have) > len(want) else block.lines[-1][0] if block.lines else block.first_line
        extra = have[len(want)][1] if len(have) > len(want) else want[len(have)][0]
        side = "README has a line the run does not print" if len(have) > len(want) else "the run prints a line the README lacks"
        return [f"{readme_name}:{where}: {block.source} output: {side}: {extra}"]
    return []


def fill(text, markers, blocks, figures, excerpts):
    """TEXT with every results marker and results-block whose source is known rewritten.
    Returns (new text, problems)."""
    problems = []
    edits = []  # (start, end, replacement) in TEXT
    for mk, new, problem in stated_figures(markers, "results", figures, "README.md"):
        if problem is not None:
            problems.append(problem)
        else:
            edits.append((mk.start, mk.end, new))
    lines = text.split("\n")
    starts = [0]
    for line in lines:
        starts.append(starts[-1] + len(line) + 1)
    for b in blocks:
        if b.source not in excerpts:
            continue
        body = "\n".join(["```"] + excerpts[b.source] + ["```"])
        edits.append((starts[b.body_start], starts[b.body_end] - 1, body))
    for start, end, new in sorted(edits, reverse=True):
        text = text[:start] + new + text[end:]
    return text, problems


def sources_to_check(markers, blocks):
    """The sources whose deterministic figures the README states (measured ones are not checked)."""
    return sorted({m.source for m in markers if m.kind == "fig"} | {b.source for b in blocks})


# ---------------------------------------------------------------------------------------------
# Running the firmware
# ---------------------------------------------------------------------------------------------

def run_firmware(ringlet, config, report, svg=None, log=None, clock=("--lockstep",)):
    """One run, in lockstep unless CLOCK says otherwise: (exit code, report JSON or None, console
    excerpt, the finished process)."""
    cmd = [str(ringlet), "--config", str(config), *clock, "--report", str(report)]
    if svg:
        cmd += ["--svg", str(svg)]
    if log:
        log(" ".join(cmd))
    if os.path.exists(report):
        os.remove(report)
    p = subprocess.run(cmd, capture_output=True, text=True)
    data = None
    if os.path.exists(report):
        with open(report, encoding="utf-8") as f:
            data = json.load(f)
    return p.returncode, data, console_excerpt(p.stdout, p.stderr), p


# Exit codes of a run that finished and wrote its report (firmware/README.md): complete,
# incomplete, safe state forced.
FINISHED = (0, 3, 4)


def cmd_check(args):
    text = read_readme(args.readme)
    name = os.path.basename(args.readme)
    markers, blocks = parse(text, name)
    sources = sources_to_check(markers, blocks)
    if not sources:
        raise BadInput(f"{args.readme}: no figure markers (<!--fig:KEY-->VALUE<!--/fig-->) to check")
    # Every name is checked before anything runs: a typo costs a second, not a mission.
    configs, plans = {}, []
    for source in sources:
        if is_eval_source(source):
            n = sum(1 for m in markers if m.source == source and m.kind == "fig")
            print(f"-- {source}: {n} figures not checked here (the vision evaluation; "
                  f"`tools/ringlet results` checks them)")
            continue
        if is_plan_source(source):
            first = min(m.line for m in markers if m.source == source)
            if args.plan_bench is None or args.maps_dir is None:
                raise BadInput(f"{name}:{first}: '{source}' needs --plan-bench and --maps-dir")
            if not (Path(args.maps_dir) / f"{source[len(PLAN_PREFIX):]}.map").is_file():
                raise BadInput(f"{name}:{first}: '{source}': {args.maps_dir} has no {source[len(PLAN_PREFIX):]}.map")
            plans.append(source)
            continue
        config = Path(args.config_dir) / f"{source}.toml"
        if not config.is_file():
            lines = sorted({m.line for m in markers if m.source == source} |
                           {b.first_line for b in blocks if b.source == source})
            raise BadInput(f"{name}:{lines[0]}: '{source}' is not a shipped configuration ({config} does not exist)")
        configs[source] = config
    os.makedirs(args.work, exist_ok=True)
    figures, excerpts, problems = {}, {}, []
    for source, config in configs.items():
        print(f"-- {source}: running {config.name} in lockstep", flush=True)
        rc, report, excerpt, p = run_firmware(args.ringlet, config, Path(args.work) / f"{source}.json",
                                              log=lambda c: print("   " + c, flush=True))
        if rc not in FINISHED or report is None:
            problems.append(f"{source}: the firmware exited {rc} without a report:\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
            continue
        figures[source] = firmware_figures(report)
        excerpts[source] = excerpt
    for source in plans:
        print(f"-- {source}: ringlet-plan-bench replan", flush=True)
        rc, report, p, _ = run_plan_bench(args.plan_bench, args.maps_dir, source, Path(args.work) / f"{source}.json")
        if report is None:
            problems.append(f"{source}: ringlet-plan-bench exited {rc}:\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
            continue
        figures[source] = plan_figures(report)
    for b in blocks:
        if b.source in excerpts:
            problems += check_block(b, excerpts[b.source], name)
    problems += check_inline(markers, figures, name)
    checked = sum(1 for m in markers if m.kind == "fig" and m.source in figures)
    checked_blocks = sum(1 for b in blocks if b.source in excerpts)
    if problems:
        print(f"{name}: {len(problems)} figure(s) disagree with the run "
              f"(update {name}; `tools/ringlet results` rewrites the output blocks):", file=sys.stderr)
        for pr in problems:
            print("  " + pr, file=sys.stderr)
        return 1
    print(f"{name}: {checked} figures and {checked_blocks} output block(s) agree with the run")
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(
        description="Check README.md's deterministic figures (<!--fig:KEY-->VALUE<!--/fig--> and the "
                    "results-block output blocks) against lockstep runs of the shipped configurations.")
    sub = ap.add_subparsers(dest="command", required=True)
    c = sub.add_parser("check", help="run the firmware for every configuration the README names and compare")
    c.add_argument("--readme", required=True, help="the README to check")
    c.add_argument("--ringlet", required=True, help="the firmware binary")
    c.add_argument("--config-dir", required=True, help="the shipped configurations (SOURCE.toml)")
    c.add_argument("--work", required=True, help="folder for the runs' reports")
    c.add_argument("--plan-bench", help="ringlet-plan-bench, for plan_bench_MAP figures")
    c.add_argument("--maps-dir", help="the maps plan_bench_MAP names (planning/maps)")
    args = ap.parse_args(argv)
    try:
        if not os.access(args.ringlet, os.X_OK) or not os.path.isfile(args.ringlet):
            raise BadInput(f"--ringlet {args.ringlet}: not an executable file")
        return cmd_check(args)
    except BadInput as e:
        print(f"readme_figures: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
