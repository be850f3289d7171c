#!/usr/bin/env python3
"""Regenerate docs/results/ (pictures and results.md) and the README's measured figures.

Called by `tools/ringlet results` after it has built the release tools; see --help. Every step is
announced; a failed step is named at the end and the exit status is 1 (2 for bad arguments). The
steps that do not depend on a failed one still run, so one failure does not hide another.
"""

import argparse
import datetime
import time
import json
import math
import os
import platform
import shlex
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import readme_figures as rf  # noqa: E402  (the README's markers: one module for the command and the test)

ROOT = Path(__file__).resolve().parent.parent
DOCS = Path("docs/results")
MODELS = Path("vision/models")
WORK = Path("out/results")

# The vision evaluation's sets (vision/README.md, "Evaluation"): Hough is tuned on the tuning set,
# both detectors are scored on the test sets; the chart is drawn for the first test set.
TUNE_SET = {"seed": 101, "count": 40}
TEST_SETS = [{"seed": 202, "count": 240}, {"seed": 303, "count": 240}]
# Each shipped configuration also runs this long on the real clock (clock_nanosleep, measured
# budgets): what the timing looks like when the host's time is what counts.
REALTIME_SECONDS = 5
DATASET_FLAGS = ["--occluded", "0.3", "-q", "--no-labels"]
# ringlet-plan-bench replan on the shipped maps (planning/maps); the first one's run is drawn.
PLAN_MAPS = ["rooms200", "forest200", "maze65"]


class Failed(Exception):
    """A step failed; the message says what."""


def say(msg):
    print(msg, flush=True)


def run(cmd, **kw):
    say("   $ " + " ".join(shlex.quote(str(c)) for c in cmd))
    p = subprocess.run([str(c) for c in cmd], capture_output=True, text=True, **kw)
    if p.returncode != 0:
        tail = (p.stdout + p.stderr).strip().splitlines()[-15:]
        raise Failed(f"{Path(str(cmd[0])).name} exited {p.returncode}:\n      " + "\n      ".join(tail))
    return p


# ---------------------------------------------------------------------------------------------
# Facts about this run
# ---------------------------------------------------------------------------------------------

def cpu_model():
    try:
        text = Path("/proc/cpuinfo").read_text(encoding="utf-8", errors="replace")[:1 << 20]
    except OSError:
        return "unknown (no /proc/cpuinfo)"
    for key in ("model name", "Model", "Hardware", "CPU part"):
        for line in text.splitlines():
            k, _, v = line.partition(":")
            if k.strip() == key and v.strip():
                return v.strip()
    return "unknown"


def load_average():
    try:
        return " ".join(Path("/proc/loadavg").read_text().split()[:3])
    except OSError:
        return "unknown"


def git(*args):
    p = subprocess.run(["git", *args], capture_output=True, text=True, cwd=ROOT)
    return p.stdout.strip() if p.returncode == 0 else ""


def facts():
    commit = git("rev-parse", "HEAD") or "unknown (not a git checkout)"
    dirty = bool(git("status", "--porcelain", "--untracked-files=no"))
    return {
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        "arch": platform.machine(),
        "cpu": cpu_model(),
        "cores": os.cpu_count(),
        "kernel": platform.release(),
        "commit": commit[:12] + (" plus uncommitted changes" if dirty else ""),
        "subject": git("log", "-1", "--format=%s"),
        "load_start": load_average(),
    }


# ---------------------------------------------------------------------------------------------
# The shipped missions
# ---------------------------------------------------------------------------------------------

def shipped_missions(config_dir):
    """(runnable, skipped): the configurations of firmware/config that run on the simulator here,
    and the others with the reason (e.g. a real camera or board)."""
    runnable, skipped = [], []
    for path in sorted(Path(config_dir).glob("*.toml")):
        try:
            cfg = tomllib.loads(path.read_text(encoding="utf-8"))
        except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as e:
            raise Failed(f"{path}: cannot read the configuration: {e}") from None
        backend = cfg.get("robot", {}).get("backend", "sim")
        camera = cfg.get("camera", {})
        if backend != "sim":
            skipped.append((path, f'robot.backend = "{backend}" (hardware)'))
        elif camera.get("enabled", False) and camera.get("backend", "sim") != "sim":
            skipped.append((path, f'camera.backend = "{camera.get("backend")}" (hardware)'))
        else:
            runnable.append(path)
    return runnable, skipped


def run_mission(ringlet, config):
    stem = config.stem
    report, svg = WORK / f"{stem}.json", DOCS / f"{stem}.svg"
    rc, data, excerpt, p = rf.run_firmware(ringlet, config, report, svg, log=lambda c: say("   $ " + c))
    (WORK / f"{stem}.out.txt").write_text(p.stdout + "\n--- stderr\n" + p.stderr, encoding="utf-8")
    if data is None:
        tail = (p.stdout + p.stderr).strip().splitlines()[-15:]
        raise Failed(f"{config}: ringlet exited {rc} without a report:\n      " + "\n      ".join(tail))
    m = data["mission"]
    say(f"   {stem}: {m['goals_reached']}/{m['goal_count']} goals, {m['mission_seconds']:.2f} s simulated, "
        f"run hash {m['run_hash']}, {m['host_seconds']:.1f} s of host time, exit {rc}")
    return {"config": config, "rc": rc, "report": data, "excerpt": excerpt, "svg": svg}


def run_realtime(ringlet, config):
    report = WORK / f"realtime_{config.stem}.json"
    rc, data, _, p = rf.run_firmware(ringlet, config, report, log=lambda c: say("   $ " + c),
                                     clock=("--realtime", "--duration", str(REALTIME_SECONDS)))
    if data is None or rc not in rf.FINISHED:
        tail = (p.stdout + p.stderr).strip().splitlines()[-15:]
        raise Failed(f"{config} on the real clock: ringlet exited {rc} without a report:\n      " + "\n      ".join(tail))
    m, fr = data["mission"], data["timing"]["frames"]
    say(f"   {config.stem}: {fr['executed']} frames, {fr['frame_overruns']} frame overruns, {fr['slips']} slips, "
        f"wake-up p99 {fr['wake_latency']['p99_us']:.0f} µs" + (f"; safe state: {m['safe_state_reason']}" if m["safe_state_forced"] else ""))
    return {"config": config, "rc": rc, "report": data}


# ---------------------------------------------------------------------------------------------
# Vision: datasets, overlays, evaluation
# ---------------------------------------------------------------------------------------------

def make_dataset(tool, seed, count):
    out = WORK / "vision" / f"seed{seed}"
    if out.exists():
        shutil.rmtree(out)  # ringlet-dataset refuses a folder holding another dataset
    run([tool, "-n", count, "--seed", seed, *DATASET_FLAGS, "-o", out])
    return out


def frame_truth(folder, index):
    return json.loads((folder / f"frame_{index:04d}.json").read_text(encoding="utf-8"))


def pick_overlay_frames(folder, count):
    """The first open-field frame (no robot close by, ball and at least three line runs in view) and
    the first frame with a robot close by and at least two line runs: the two README pictures."""
    open_field = robot = None
    for i in range(count):
        t = frame_truth(folder, i)
        lines = len(t["lines"])
        ball = t.get("ball") or {}
        if open_field is None and not t["occluders"] and ball.get("visible") and lines >= 3:
            open_field = i
        if robot is None and t["occluders"] and lines >= 2:
            robot = i
        if open_field is not None and robot is not None:
            return open_field, robot
    raise Failed(f"{folder}: no open-field frame and robot-close-by frame among its {count} frames")


def overlay(tool, folder, index, out):
    t = frame_truth(folder, index)
    k, mount, head = t["intrinsics"], t["mount"], t["head"]
    run([tool, folder / f"frame_{index:04d}.png", "--overlay", out,
         "--width", k["width"], "--height", k["height"], "--fx", repr(k["fx"]), "--fy", repr(k["fy"]),
         "--cx", repr(k["cx"]), "--cy", repr(k["cy"]), "--pivot-height", repr(mount["pivot_height"]),
         "--camera-forward", repr(mount["forward"]), "--camera-up", repr(mount["up"]),
         "--yaw", repr(math.degrees(head["yaw"])), "--pitch", repr(math.degrees(head["pitch"])),
         "--ball-model", MODELS / "ball.hog", "--robot-model", MODELS / "robot.hog"])


def evaluate(tool, test_set, tune_set, excluded, seed, svg):
    out = WORK / f"vision_eval_{seed}.json"
    # Lines against Hough without the classifiers (the tool's default is the shipped models), as
    # these figures have always been made.
    cmd = [tool, test_set, "--tune-set", tune_set, "--json", out, "-q", "--ball-model", "none", "--robot-model", "none"]
    for d in excluded:
        cmd += ["--disjoint-from", d]
    if svg:
        cmd += ["--svg", svg]
    run(cmd)
    return json.loads(out.read_text(encoding="utf-8"))


# ---------------------------------------------------------------------------------------------
# results.md
# ---------------------------------------------------------------------------------------------

def f(v, d=1):
    return f"{v:.{d}f}"


def task_table(t):
    md = ["| task | rate | budget | policy | runs | CPU p50 | CPU p99 | CPU p99 / budget | CPU max | wall p99 | model p99 | overruns (judged) | measured overruns | skipped | degraded |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for k in t["tasks"]:
        md.append(f"| {k['name']} | {f(k['rate_hz'])} Hz | {f(k['budget_us'])} | {k['policy']} | {k['runs']} "
                  f"| {f(k['cpu']['p50_us'])} | {f(k['cpu']['p99_us'])} | {f(100 * k['cpu']['p99_us'] / k['budget_us'])} % "
                  f"| {f(k['cpu']['max_us'])} | {f(k['wall']['p99_us'])} | {f(k['model']['p99_us'])} "
                  f"| {k['overruns']} | {k['measured_overruns']} | {k['skipped']} | {k['degraded_runs']} |")
    return md


def results_markdown(fx, missions, skipped, realtime, vision, plans, commands):
    md = ["# Ringlet: measured results", "",
          "Generated by `tools/ringlet results`; do not edit (run the command again). The deterministic",
          "figures (hashes, goals, distance, frame counts) are the same on every machine and are checked",
          "against README.md by the CTest `ReadmeFigures`; the times are this machine's, at this load.", "",
          "| | |", "|---|---|",
          f"| date | {fx['date']} |",
          f"| machine | {fx['arch']}, {fx['cpu']}, {fx['cores']} cores (Linux {fx['kernel']}) |",
          f"| load average (1, 5, 15 min) | {fx['load_start']} at the start, {fx['load_end']} at the end |",
          f"| commit | `{fx['commit']}` {fx['subject']} |",
          "| build | `release` preset (`-O2`), every mission in lockstep |", ""]

    md += ["## Shipped missions", "",
           "| configuration | goals | collisions | distance | mission time | frames | vision frames | overruns (judged) | skipped | run hash | trajectory hash | exit | host time |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in missions:
        m, t = r["report"]["mission"], r["report"]["timing"]
        det, meas = rf.firmware_figures(r["report"])
        md.append(f"| `{r['config'].name}` | {det['goals']} | {det['collisions']} | {f(det['distance_m'], 2)} m "
                  f"| {f(det['mission_s'], 2)} s | {det['frames']} | {det.get('vision.frames', '—')} "
                  f"| {det['overruns']} | {det['skipped']} | `{det['run_hash']}` | `{det['trajectory_hash']}` "
                  f"| {r['rc']} | {f(meas['host_s'], 2)} s |")
    for path, why in skipped:
        md.append(f"| `{path.name}` | not run here: {why} | | | | | | | | | | | |")
    md.append("")

    for r in missions:
        m, t, sch = r["report"]["mission"], r["report"]["timing"], r["report"]["schedule"]
        md += [f"## `{r['config'].name}`", "", f"![{r['config'].stem}]({r['svg'].name})", ""]
        if m.get("vision"):
            v = m["vision"]
            n = v["frames"] or 1
            md.append(f"Vision: {v['frames']} frames, lines in {f(100 * v['with_lines'] / n)} % "
                      f"({f(v['lines'] / n)} per frame), ball in {f(100 * v['with_ball'] / n)} %, robots {v['robots']}, "
                      f"cut by the deadline {v['cut']} (the line search {v['lines_cut']}), degraded {v['degraded']}, "
                      f"bad {v['bad_frames']}, "
                      f"missed {v['missed_frames']}.")
            if v.get("stage_model"):
                md.append("Vision by stage, modelled board time per frame (p50 / p99 µs): " + ", ".join(
                    f"{name} {f(h['p50_us'], 0)} / {f(h['p99_us'], 0)}" for name, h in v["stage_model"].items()) + ".")
        h = m.get("head_tracking")
        if h and h["frames"]:
            md.append(f"Head on the true ball (yaw within 5°): {f(100 * h['on_target_share'])} % of {h['frames']} "
                      f"frames, mean error {f(h['mean_error_deg'], 2)}°, max {f(h['max_error_deg'])}°.")
        md += ["", f"Timing per task in lockstep ({t['frames']['executed']} frames of {f(t['period_us'], 0)} µs; "
                   f"budgets judged on: {t['budgets_judged_on']}; times in µs):", ""]
        md += task_table(t)
        md += ["",
               f"LLFSM schedule ({sch['turns']} turns; ringlet wall time in µs):", "",
               "| machine | per turn | ringlets | mean | max | final state |", "|---|---|---|---|---|---|"]
        for mc in sch["machines"]:
            md.append(f"| {mc['name']} | {mc['ringlets_per_turn']} | {mc['ringlets']} | {f(mc['mean_us'], 2)} "
                      f"| {f(mc['max_us'], 1)} | {mc['final_state']} |")
        md.append("")

    if realtime:
        md += [f"## Real clock ({REALTIME_SECONDS} s of each configuration)", "",
               "`ringlet --realtime`: the executive sleeps to absolute deadlines with `clock_nanosleep` and the",
               "policies act on measured time (thread CPU time: `budgets_judged_on = \"cpu\"`). No SCHED_FIFO,",
               "no `mlockall` here: a shared desktop, not the robot.", ""]
        for r in realtime:
            t, m = r["report"]["timing"], r["report"]["mission"]
            fr = t["frames"]
            safe = f"; safe state forced ({m['safe_state_reason']})" if m["safe_state_forced"] else ""
            md += [f"### `{r['config'].name}`", "",
                   f"{fr['executed']} frames of {f(t['period_us'], 0)} µs, judged on: {t['budgets_judged_on']}; "
                   f"frame overruns {fr['frame_overruns']}, slips {fr['slips']}; busy p99 {f(fr['busy']['p99_us'])} µs; "
                   f"wake-up latency p99 {f(fr['wake_latency']['p99_us'])} µs, max {f(fr['wake_latency']['max_us'])} µs; "
                   f"exit {r['rc']}{safe}. Times in µs:", ""]
            md += task_table(t) + [""]

    if not vision:
        md += ["## Vision", "", "Not regenerated by this run (`--no-vision`, or a vision step failed): the vision "
               "pictures here are from an earlier run.", ""]
    else:
        md += ["## Vision", "",
               "Ringlet vs OpenCV Canny + HoughLinesP on rendered frames (`ringlet-vision-eval`; protocol in",
               "[vision/README.md](../../vision/README.md#evaluation-ringlet-vs-canny--houghlinesp)). Times: one thread, "
               "this machine, at this load.", ""]
        for e in vision["evals"]:
            j = e["report"]
            md += [f"Test set: {j['test_set']}  ", f"tuning set: {j['tuning_set']}  "]
            for x in j.get("excluded_sets", []):
                md.append(f"excluded: {x}  ")
            md += [f"checked: {j['disjointness']}", "",
                   "| detector | precision | recall | F1 | detections | true segments (recalled) | median ms | p99 ms |",
                   "|---|---|---|---|---|---|---|---|"]
            for key in ("ringlet", "hough"):
                d = j["detectors"][key]
                md.append(f"| {d['name']} | {f(d['precision'], 3)} | {f(d['recall'], 3)} | {f(d['f1'], 3)} "
                          f"| {d['detections_scored']} | {d['truths']} ({d['recalled']}) | {f(d['time_ms']['median'], 3)} "
                          f"| {f(d['time_ms']['p99'], 3)} |")
            md += ["", f"Speed ratio (Hough median / Ringlet median): {f(j['speed_ratio'], 2)}×.", ""]
            if e.get("svg"):
                md += [f"![Ringlet vs Canny + HoughLinesP]({Path(e['svg']).name})", ""]
        md += [f"Overlays (`ringlet-vision --overlay` with the shipped ball and robot models; green: lines, blue: "
               f"horizon, magenta: centre circle, orange: balls, cyan: robots' boxes and foot points) of frame {vision['open']} "
               f"(open field) and frame {vision['robot']} (a robot close by) of the seed {TEST_SETS[0]['seed']} test set:", "",
               "| open field | a robot close by |", "|---|---|",
               "| ![overlay](vision_overlay_field.png) | ![overlay with a robot](vision_overlay_robot.png) |", ""]

    if plans:
        md += ["## Planning: D* Lite against repeated A*", "",
               "`ringlet-plan-bench replan` on the shipped MovingAI maps: the robot knows nothing at first, sees",
               "obstacles within 5 cells as it drives, and replans with both planners from the same cells whenever it",
               "sees a new one. Expansions are deterministic; times are this machine's.", "",
               "| map | problems (reached) | replans | D* Lite expansions | A* expansions | ratio | D* Lite s | A* s | time ratio |",
               "|---|---|---|---|---|---|---|---|---|"]
        for source, r in plans:
            t = r["totals"]
            md.append(f"| {source[len('plan_bench_'):]} | {t['problems']} ({t['reached']}) | {t['replans']} | "
                      f"{t['dstar_lite_expansions']} | {t['astar_expansions']} | {t['expansion_ratio']:.1f}× | "
                      f"{t['dstar_lite_seconds']:.3f} | {t['astar_seconds']:.3f} | {t['time_ratio']:.1f}× |")
        md += ["", f"![D* Lite replanning on rooms200](plan_replan_{plans[0][0][len('plan_bench_'):]}.svg)", ""]
    md += ["## How each file was made", "", "```"] + commands + ["```", ""]
    return "\n".join(md)


def for_each_config(configs, run_one):
    """RUN_ONE(config) for every configuration in turn, so that one failing hides no other: (the results,
    the problems in configuration order). RUN_ONE returns (result, problem or None), or raises Failed
    for a configuration that gave no result."""
    results, problems = [], []
    for config in configs:
        try:
            result, problem = run_one(config)
        except Failed as e:
            problems.append(str(e))
            continue
        results.append(result)
        if problem is not None:
            problems.append(problem)
    return results, problems


# ---------------------------------------------------------------------------------------------
# The command
# ---------------------------------------------------------------------------------------------

def main(argv=None):
    ap = argparse.ArgumentParser(
        prog="tools/results.py",
        description="Regenerate docs/results/ (mission pictures, vision overlays and chart, results.md) and "
                    "README.md's measured figures, then check its deterministic ones. Run from the repository "
                    "root with the release tools built (tools/ringlet results does both).")
    ap.add_argument("--build-dir", default="build/release", help="build tree with the tools (default: %(default)s)")
    ap.add_argument("--vision-exclude", action="append", default=[], metavar="DIR",
                    help="a ringlet-dataset folder the vision test sets must share no frame with (repeatable; "
                         "e.g. the generator-v1 sets Ringlet's parameters were chosen on)")
    ap.add_argument("--no-vision", action="store_true", help="skip the datasets, overlays and evaluation "
                    "(about a minute); their pictures and README figures are left as they are")
    args = ap.parse_args(argv)

    os.chdir(ROOT)
    started = time.time() - 1  # files written from here on are this run's
    b = Path(args.build_dir)
    tools = {"ringlet": b / "firmware/ringlet", "dataset": b / "tools/dataset/ringlet-dataset",
             "vision": b / "vision/tools/ringlet-vision", "eval": b / "vision/tools/ringlet-vision-eval",
             "plan_bench": b / "planning/tools/plan_bench/ringlet-plan-bench"}
    needed = ["ringlet", "plan_bench"] + ([] if args.no_vision else ["dataset", "vision", "eval"])
    missing = [str(tools[t]) for t in needed if not os.access(tools[t], os.X_OK)]
    bad = [d for d in args.vision_exclude if not Path(d, "frame_0000.json").is_file()]
    if missing or bad:
        for m in missing:
            print(f"results: {m}: not built (tools/ringlet results builds it)", file=sys.stderr)
        for d in bad:
            print(f"results: --vision-exclude {d}: not a ringlet-dataset folder (no frame_0000.json)", file=sys.stderr)
        return 2
    DOCS.mkdir(parents=True, exist_ok=True)
    WORK.mkdir(parents=True, exist_ok=True)

    steps = ["this machine and commit", "shipped missions", "shipped configurations on the real clock", "vision datasets", "vision overlays",
             "vision evaluation", "planning benchmark", "results.md", "README.md measured figures",
             "README.md deterministic figures"]
    failures = []
    n = len(steps)
    state = {}

    def step(i, fn):
        say(f"\n[{i + 1}/{n}] {steps[i]}")
        try:
            fn()
            return True
        except Failed as e:
            failures.append(f"{steps[i]}: {e}")
            say(f"   FAILED: {e}")
            return False

    commands = []

    def s_facts():
        state["facts"] = facts()
        fx = state["facts"]
        say(f"   {fx['date']}; {fx['arch']}, {fx['cpu']}, {fx['cores']} cores; commit {fx['commit']}; "
            f"load {fx['load_start']}")

    def s_missions():
        runnable, skipped = shipped_missions("firmware/config")
        state["skipped"] = skipped
        for path, why in skipped:
            say(f"   {path}: not run here: {why}")

        def one(config):
            r = run_mission(tools["ringlet"], config)
            commands.append(f"{r['svg']}: ringlet --config {config} --lockstep --report {WORK}/{config.stem}.json "
                            f"--svg {r['svg']}")
            return r, f"{config}: the mission ended with exit {r['rc']} (not complete)" if r["rc"] != 0 else None

        missions, problems = for_each_config(runnable, one)
        state["missions"] = missions
        if problems:
            raise Failed("; ".join(problems))

    def s_realtime():
        runnable, _ = shipped_missions("firmware/config")

        def one(config):
            r = run_realtime(tools["ringlet"], config)
            commands.append(f"{WORK}/realtime_{config.stem}.json: ringlet --config {config} --realtime "
                            f"--duration {REALTIME_SECONDS} --report {WORK}/realtime_{config.stem}.json")
            return r, None

        runs, problems = for_each_config(runnable, one)
        state["realtime"] = runs
        if problems:
            raise Failed("; ".join(problems))

    def vision_skipped(needs_sets=True):
        """True (and says so) when --no-vision skips this step; Failed when it needs the datasets and
        the step that makes them failed."""
        if args.no_vision:
            say("   skipped (--no-vision)")
            return True
        if needs_sets and "sets" not in state:
            raise Failed("no datasets (the step before failed)")
        return False

    def s_datasets():
        if vision_skipped(needs_sets=False):
            return
        sets = {"tune": make_dataset(tools["dataset"], TUNE_SET["seed"], TUNE_SET["count"])}
        for t in TEST_SETS:
            sets[t["seed"]] = make_dataset(tools["dataset"], t["seed"], t["count"])
        state["sets"] = sets
        flags = " ".join(DATASET_FLAGS)
        for t in [TUNE_SET] + TEST_SETS:
            commands.append(f"{WORK}/vision/seed{t['seed']}: ringlet-dataset -n {t['count']} --seed {t['seed']} {flags}")

    def s_overlays():
        if vision_skipped():
            return
        folder = state["sets"][TEST_SETS[0]["seed"]]
        open_i, robot_i = pick_overlay_frames(folder, TEST_SETS[0]["count"])
        say(f"   open field: frame {open_i}; a robot close by: frame {robot_i}")
        for i, name in ((open_i, "vision_overlay_field.png"), (robot_i, "vision_overlay_robot.png")):
            overlay(tools["vision"], folder, i, DOCS / name)
            commands.append(f"{DOCS / name}: ringlet-vision {folder}/frame_{i:04d}.png --overlay {DOCS / name} "
                            f"--ball-model {MODELS / 'ball.hog'} --robot-model {MODELS / 'robot.hog'} "
                            f"(camera flags from frame_{i:04d}.json)")
        state["overlays"] = (open_i, robot_i)

    def s_eval():
        if vision_skipped():
            return
        evals = []
        for k, t in enumerate(TEST_SETS):
            svg = DOCS / "vision_eval.svg" if k == 0 else None
            j = evaluate(tools["eval"], state["sets"][t["seed"]], state["sets"]["tune"], args.vision_exclude,
                         t["seed"], svg)
            d = j["detectors"]
            say(f"   seed {t['seed']}: F1 Ringlet {d['ringlet']['f1']:.3f} vs Hough {d['hough']['f1']:.3f}; "
                f"median {d['ringlet']['time_ms']['median']:.3f} vs {d['hough']['time_ms']['median']:.3f} ms")
            evals.append({"seed": t["seed"], "report": j, "svg": svg})
            excl = "".join(f" --disjoint-from {x}" for x in args.vision_exclude)
            made = svg or WORK / f"vision_eval_{t['seed']}.json"
            commands.append(f"{made}: ringlet-vision-eval {state['sets'][t['seed']]} --tune-set {state['sets']['tune']}{excl} "
                            f"--json {WORK}/vision_eval_{t['seed']}.json --ball-model none --robot-model none"
                            + (f" --svg {svg}" if svg else ""))
        state["evals"] = evals

    def s_plan():
        runs, problems = [], []
        for k, m in enumerate(PLAN_MAPS):
            source = f"{rf.PLAN_PREFIX}{m}"
            svg = DOCS / f"plan_replan_{m}.svg" if k == 0 else None
            rc, report, p, cmd = rf.run_plan_bench(tools["plan_bench"], "planning/maps", source, WORK / f"{source}.json", svg)
            if report is None:
                problems.append(f"{m}: ringlet-plan-bench exited {rc}: {p.stderr.strip()[-500:]}")
                continue
            t = report["totals"]
            say(f"   {m}: {t['problems']} problems, {t['replans']} replans; expansions D* Lite {t['dstar_lite_expansions']} "
                f"vs A* {t['astar_expansions']} ({t['expansion_ratio']:.1f}x fewer), time {t['time_ratio']:.1f}x")
            commands.append(f"{svg or WORK / (source + '.json')}: ringlet-plan-bench " + " ".join(str(c) for c in cmd[1:]))
            runs.append((source, report))
        state["plans"] = runs
        if problems:
            raise Failed("; ".join(problems))

    def s_markdown():
        if "missions" not in state:
            raise Failed("no mission reports (the step before failed)")
        state["facts"]["load_end"] = load_average()
        vision = None
        if "evals" in state and "overlays" in state:
            vision = {"evals": state["evals"], "open": state["overlays"][0], "robot": state["overlays"][1]}
        text = results_markdown(state["facts"], state["missions"], state.get("skipped", []), state.get("realtime", []),
                                vision, state.get("plans", []), commands)
        (DOCS / "results.md").write_text(text, encoding="utf-8")
        say(f"   wrote {DOCS / 'results.md'}")

    def figures():
        out = {r["config"].stem: rf.firmware_figures(r["report"]) for r in state.get("missions", [])}
        for r in state.get("realtime", []):
            out[f"realtime_{r['config'].stem}"] = rf.firmware_figures(r["report"])
        for e in state.get("evals", []):
            out[f"vision_eval_{e['seed']}"] = rf.eval_figures(e["report"])
        for source, report in state.get("plans", []):
            out[source] = rf.plan_figures(report)
        return out

    def s_readme_fill():
        text = rf.read_readme("README.md")
        markers, blocks = rf.parse(text, "README.md")
        excerpts = {r["config"].stem: r["excerpt"] for r in state.get("missions", [])}
        new, problems = rf.fill(text, markers, blocks, figures(), excerpts)
        if new != text:
            Path("README.md").write_text(new, encoding="utf-8")
        filled = sum(1 for m in markers if m.kind == "results" and m.source in figures())
        say(f"   {filled} measured figures and {sum(1 for b in blocks if b.source in excerpts)} output block(s) written")
        if problems:
            raise Failed("; ".join(problems))

    def s_readme_check():
        text = rf.read_readme("README.md")
        markers, blocks = rf.parse(text, "README.md")
        figs = figures()
        excerpts = {r["config"].stem: r["excerpt"] for r in state.get("missions", [])}
        problems = rf.check_inline(markers, figs, "README.md")
        for blk in blocks:
            if blk.source in excerpts:
                problems += rf.check_block(blk, excerpts[blk.source], "README.md")
        unchecked = sorted({m.source for m in markers if m.kind == "fig" and m.source not in figs})
        checked = sum(1 for m in markers if m.kind == "fig" and m.source in figs)
        say(f"   {checked} figures checked" + (f"; not checked (not run): {', '.join(unchecked)}" if unchecked else ""))
        if problems:
            raise Failed("README.md's figures disagree with this run (update them there):\n      "
                         + "\n      ".join(problems))

    try:
        for i, fn in enumerate([s_facts, s_missions, s_realtime, s_datasets, s_overlays, s_eval, s_plan, s_markdown,
                                s_readme_fill, s_readme_check]):
            step(i, fn)
    except rf.BadInput as e:
        failures.append(str(e))

    say("")
    if failures:
        print(f"results: FAILED ({len(failures)} of {n} steps):", file=sys.stderr)
        for x in failures:
            print("  - " + x, file=sys.stderr)
        return 1
    written = sorted(p.name for p in DOCS.iterdir() if p.is_file() and p.stat().st_mtime >= started)
    say(f"results: OK: wrote {DOCS}/{{{','.join(written)}}}; README.md's measured figures written and its "
        "deterministic figures agree")
    return 0


if __name__ == "__main__":
    sys.exit(main())
