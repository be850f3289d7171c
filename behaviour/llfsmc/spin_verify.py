#!/usr/bin/env python3
"""Model-checks a machine or a schedule with spin: llfsmc --promela, `spin -a`, the host C compiler
builds `pan` (with the LTL claims; without a claim for the assertions), pan runs
every property; reports states, depth and time from pan's output. A failed property's trail is
replayed (`spin -t`) and printed as ringlets: turn, machine, state before -> after, inputs, outputs.

    spin_verify.py MODEL.machine|SCHEDULE.schedule --work DIR [--ringlets N] [--expect-fail PROP]...
                   [--cc gcc] [--spin spin]

Exit 0 when every property holds (or, with --expect-fail, when exactly those properties fail with a
readable counterexample); 1 otherwise. Standard library only.
"""

import argparse
import json
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SCALE = 1000


def run(cmd, cwd, timeout=600):
    """Exit status and output of `cmd`; a run past `timeout` seconds is a failure that says so."""
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired as e:
        out = (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
        return 124, out + f"\n{' '.join(cmd)}: stopped after {timeout} s (not verified)\n"
    return p.returncode, p.stdout + p.stderr


def pan_figures(out):
    f = {}
    m = re.search(r"depth reached (\d+), errors: (\d+)", out)
    if m:
        f["depth"], f["errors"] = int(m.group(1)), int(m.group(2))
    m = re.search(r"(\d+) states, stored", out)
    if m:
        f["states"] = int(m.group(1))
    m = re.search(r"pan: elapsed time ([\d.e+-]+) seconds", out)
    f["time_s"] = float(m.group(1)) if m else 0.0
    return f


def value(name, v, meta):
    if name in meta["fixed"]:
        return f"{int(v) / SCALE:g}"
    if name in meta.get("bools", ()):
        return "true" if v == "1" else "false"
    return v


def readable_trace(out, meta):
    """spin -t's printf lines (@T @I @R @O @A) as turns of ringlets."""
    names = {m["name"]: m["states"] for m in meta["machines"]}
    lines, turn, inputs, outputs = [], 0, [], []
    for raw in out.splitlines():
        s = raw.strip()
        if "START OF CYCLE" in s:
            lines.append("  <<< the trace repeats from here (a cycle that violates the property) >>>")
        if s.startswith("@T"):
            turn += 1
            inputs, outputs = [], []
            lines.append(f"turn {turn}:")
        elif s.startswith("@I "):
            _, name, v = s.split()
            inputs.append(f"{name}={value(name, v, meta)}")
        elif s.startswith("@R "):
            parts = s.split()
            if len(parts) == 5:
                m, a, b, susp = parts[1], int(parts[2]), int(parts[3]), parts[4]
                if len(inputs) and not any(x.startswith("  inputs") for x in lines[-3:]):
                    lines.append("  inputs: " + ", ".join(inputs))
                st = names[m]
                change = f"{st[a]} -> {st[b]}" if a != b else f"{st[a]}"
                lines.append(f"  ringlet {m}: {change}{' (suspended)' if susp == '1' else ''}")
        elif s.startswith("@O "):
            _, name, v = s.split()
            if name not in meta["inputs"]:
                outputs.append(f"{name}={value(name, v, meta)}")
            if outputs and raw is not None:
                pass
        elif s.startswith("@A "):
            lines.append(f"  assertion {s.split()[1]} fails here")
        if s.startswith("@O ") and lines and not lines[-1].startswith("  outputs"):
            lines.append("  outputs: " + ", ".join(outputs))
        elif s.startswith("@O ") and lines:
            lines[-1] = "  outputs: " + ", ".join(outputs)
    return "\n".join(lines)


def kripke_label(names, values, meta):
    states = {m["name"]: m["states"] for m in meta["machines"]}
    parts = []
    for n, v in zip(names, values):
        if n.endswith("_st") and n[:-3] in states:
            parts.append(f"{n[:-3]}: {states[n[:-3]][int(v)]}")
        elif n.endswith("_susp") and n[:-5] in states:
            if v != "0":
                parts[-1] += " (suspended)" if parts else ""
        elif n.endswith(("_ent", "_req")) and n[:-4] in states:
            continue
        elif n.endswith("_t") and n[:-2] in states:
            if v != "0":
                parts.append(f"{n[:-2]} clock: {v} turns")
        elif n.startswith("wb_"):
            field = n[3:].replace("_", ".", 1)
            parts.append(f"{field} = {value(field, v, meta)}")
    return "\\n".join(parts)


def write_kripke(args, meta):
    """Reachable turn-end states and the turns between them, from pan's own search (-DPRINTF)."""
    work = os.path.join(args.work, "kripke")
    os.makedirs(work, exist_ok=True)
    with open(os.path.join(args.work, "model.pml"), encoding="utf-8") as f, \
            open(os.path.join(work, "model.pml"), "w", encoding="utf-8") as g:
        g.write(f.read())
    for cmd in ([args.spin, "-DKRIPKE", "-a", "model.pml"],
                [args.cc, "-O0", "-w", "-DPRINTF", "-DSAFETY", "-DNOCLAIM", "-DVECTORSZ=4096", "-o", "pan", "pan.c"]):
        rc, out = run(cmd, work)
        if rc:
            print(out)
            return 1
    rc, out = run(["./pan", "-m1000000", "-w20"], work)
    names = meta["state_vector"]
    edges, nodes = set(), {}
    for line in out.splitlines():
        if line.startswith("@K "):
            a, b = line[3:].split(" > ")
            for t in (a, b):
                nodes.setdefault(t, len(nodes))
            edges.add((a, b))
    if len(nodes) > args.kripke_max:
        print(f"Kripke structure: {len(nodes)} states, {len(edges)} turns: more than --kripke-max "
              f"{args.kripke_max}, not drawn")
        return 0
    init = " ".join("0" for _ in names)
    lines = ["digraph kripke {", "  rankdir=LR;", '  node [shape=box, fontsize=9, fontname="Helvetica"];',
             f'  label="Kripke structure of {os.path.basename(args.model)}: {len(nodes)} turn-end states '
             f'(the first is before the first turn), {len(edges)} turns";']
    for t, i in sorted(nodes.items(), key=lambda x: x[1]):
        lines.append(f'  s{i} [label="{kripke_label(names, t.split(), meta)}"{", style=bold" if i == 0 else ""}];')
    for a, b in sorted(edges, key=lambda e: (nodes[e[0]], nodes[e[1]])):
        lines.append(f"  s{nodes[a]} -> s{nodes[b]};")
    lines.append("}")
    with open(args.kripke, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    print(f"Kripke structure: {len(nodes)} states, {len(edges)} turns -> {args.kripke}")
    del init
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("model")
    ap.add_argument("--work", required=True)
    ap.add_argument("--ringlets", type=int, default=1)
    ap.add_argument("--period-ms", type=int, help="one turn of a single machine in ms (default: llfsmc's, 10)")
    ap.add_argument("--expect-fail", action="append", help="a property that must fail (repeatable)")
    ap.add_argument("--kripke", help="also write the reachable Kripke structure (turn-end states) as Graphviz")
    ap.add_argument("--kripke-max", type=int, default=400, help="refuse to draw more states than this")
    ap.add_argument("--cc", default="gcc")
    ap.add_argument("--spin", default="spin")
    args = ap.parse_args(argv)
    os.makedirs(args.work, exist_ok=True)
    pml = os.path.join(args.work, "model.pml")
    cmd = [sys.executable, os.path.join(HERE, "llfsmc.py"), os.path.abspath(args.model), "--promela", pml]
    if not args.model.endswith(".schedule"):
        cmd += ["--ringlets", str(args.ringlets)]
        if args.period_ms:
            cmd += ["--period-ms", str(args.period_ms)]
    rc, out = run(cmd, args.work)
    if rc:
        sys.stdout.write(out)
        return 1
    with open(pml + ".json", encoding="utf-8") as f:
        meta = json.load(f)
    for m in meta["machines"]:
        for n in m["notes"]:
            print(f"abstracted: {n}")
    rc, out = run([args.spin, "-a", "model.pml"], args.work)
    if rc:
        print(out)
        print("spin -a failed")
        return 1
    # Building pan is most of the time: one build for the LTL claims, and one without a claim for
    # the assertions (a claim run prunes the search where the claim dies, so it does not check the
    # assertions everywhere) only when the model has assertions.
    ltl = [p["name"] for p in meta["properties"] if p["kind"] == "ltl"]
    asserts = [p["name"] for p in meta["properties"] if p["kind"] == "assert"]
    builds = ([("pan_safety", ["-DNOCLAIM", "-DSAFETY"])] if asserts or not ltl else []) + \
             ([("pan_ltl", ["-DNOREDUCE"])] if ltl else [])
    for exe, flags in builds:
        # -Og: the schedules' products search in half the time of -O0, and PlanExecute's pan.c
        # compiles in 14 s (-O1: 37 s, -O0: 4 s but slower searches).
        rc, out = run([args.cc, "-Og", "-w", *flags, "-DVECTORSZ=4096", "-o", exe, "pan.c"], args.work)
        if rc:
            print(out)
            print(f"{args.cc} failed to build pan")
            return 1
    runs = []
    if asserts or not ltl:
        runs.append(("assertions" + (f" ({', '.join(asserts)})" if asserts else ""), "assertions",
                     ["./pan_safety", "-m1000000", "-w20"]))
    runs += [(name, name, ["./pan_ltl", "-a", "-m1000000", "-w20", "-N", name]) for name in ltl]
    if args.expect_fail:
        # A planted bug shows that the named properties can fail; that the others hold is the
        # shipped model's own run, so only the named ones are searched (the searches are the cost).
        runs = [r for r in runs if any(r[1] == e or r[1].endswith("_" + e) for e in args.expect_fail)]
    failed, readable, results = [], {}, []
    for label, pname, command in runs:
        t0 = time.monotonic()
        rc, out = run(command, args.work)
        fig = pan_figures(out)
        wall = time.monotonic() - t0
        if "errors" not in fig:
            print(out)
            print(f"{pname}: could not read pan's output")
            return 1
        # A search cut off at the depth limit proves nothing: that is a failure too.
        truncated = "max search depth too small" in out
        ok = fig["errors"] == 0 and "violated" not in out and not truncated
        if truncated:
            print(f"{pname}: the search hit pan's depth limit (-m): not verified")
        if not ok and re.search(r"assertion violated 0 \(", out):  # our assert(false), not the claim
            pname = "assertions"
        print(f"{'HOLDS' if ok else 'FAILS'} {label}: {fig.get('states', 0)} states, depth {fig['depth']}, "
              f"{fig['time_s']:.2f} s (pan), {wall:.2f} s wall")
        results.append((pname, ok, fig))
        if not ok:
            failed.append(pname)
            trail_cmd = [args.spin, "-t", "-B", "model.pml"]  # the trail names its claim
            rc, tout = run(trail_cmd, args.work)
            trace = readable_trace(tout, meta).split("\nturn ")
            keep = 8  # the last turns lead into the violation; earlier ones are the search's detour
            if len(trace) > keep:
                trace = [f"... {len(trace) - keep} earlier turns" ] + trace[-keep:]
            print(f"counterexample for {pname}:")
            print("\nturn ".join(trace))
            readable[pname] = any(" ringlet " in t for t in trace)
            for f in os.listdir(args.work):
                if f.endswith(".trail"):
                    os.remove(os.path.join(args.work, f))
    if args.kripke:
        status = write_kripke(args, meta)
        if status:
            return status
    if args.expect_fail:
        # Every expected property fails (a machine's are named Machine_property), each with a
        # counterexample that shows ringlets.
        def matches(f, e):
            return f == e or f.endswith("_" + e)
        wanted_ok = all(any(matches(f, e) for f in failed) for e in args.expect_fail)
        extra = [f for f in failed if not any(matches(f, e) for e in args.expect_fail)]
        if wanted_ok and not extra and all(readable.get(f) for f in failed):
            print(f"as expected, {', '.join(args.expect_fail)} fail(s) with a readable counterexample")
            return 0
        print(f"expected {args.expect_fail} to fail with a readable counterexample; failed: {failed or 'none'}")
        return 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
