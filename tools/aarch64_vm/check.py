#!/usr/bin/env python3
"""Checks what the emulated aarch64 Linux reported (tools/aarch64_vm/README.md).

Usage: check.py CONSOLE_LOG OUT_DIR

Reads the runs framed by tools/aarch64_vm/init on the serial console and asserts:
  - the kernel is PREEMPT_RT and vcan0 came up;
  - `ringlet --check` accepts the CAN configuration;
  - the courtyard mission through vcan0 reached every goal with 0 collisions (the board's own
    count), the board stayed alive and no frame was malformed;
  - board killed: the firmware's CTRL_SAFE_STATE (reason 4, heartbeat lost) came within
    [can] heartbeat_timeout_ms (+ SLACK_MS) of the board's last heartbeat, on the bus's time;
  - firmware killed: the board's BOARD_FAULT (command timeout) came within its command timeout
    (+ SLACK_MS) of the last CTRL_DRIVE, and the car stopped.
Writes OUT_DIR/results.json and OUT_DIR/results.md (the README's table), prints the figures, and
exits 1 naming every failed check. Timing figures from the VM are emulated: they prove nothing
about the robot's timing and are labelled so.
"""
import json
import re
import sys
from pathlib import Path

# A side notices the other's silence at its next activation (10 ms periods), which emulation on a
# shared host can delay by a good deal more (one activation of 1.6 s was seen on a loaded host): the slack on both limits.
SLACK_MS = 300


def sections(text):
    out, name, lines = {}, None, []
    for line in text.splitlines():
        line = line.rstrip("\r")
        m = re.match(r"^(==>|<==) RINGLET-VM (\S+)$", line)
        if m and m.group(1) == "==>":
            name, lines = m.group(2), []
        elif m and name == m.group(2):
            out[name] = "\n".join(lines)
            name = None
        elif name is not None:
            lines.append(line)
    return out


def can_frames(log):
    """candump -L lines: (time s, id, data bytes)."""
    frames = []
    for line in log.splitlines():
        m = re.match(r"^\((\d+\.\d+)\) \S+ ([0-9A-F]{3})#([0-9A-F]*)$", line.strip())
        if m:
            frames.append((float(m.group(1)), int(m.group(2), 16), bytes.fromhex(m.group(3))))
    return frames


def exit_status(text):
    m = re.search(r"^exit (\d+)$", text, re.M)
    return int(m.group(1)) if m else None


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    console, out_dir = Path(sys.argv[1]), Path(sys.argv[2])
    try:
        text = console.read_bytes().decode("utf-8", "replace")
    except OSError as e:
        print(f"check.py: {console}: {e.strerror}", file=sys.stderr)
        return 1
    runs = sections(text)
    failures, results = [], {"emulated": True}

    def need(ok, what):
        if not ok:
            failures.append(what)
        return ok

    if not need("RINGLET-VM: kernel" in text, "the VM did not boot (no 'RINGLET-VM: kernel' line on the console)"):
        tail = "\n".join(text.splitlines()[-15:])
        print(f"check.py: FAILED: {failures[0]}; the console ends with:\n{tail}", file=sys.stderr)
        return 1
    m = re.search(r"RINGLET-VM: kernel (\S+), (\S+), (\d+) CPUs", text)
    if m:
        results["kernel"] = m.group(1)
        need(m.group(2) == "aarch64", f"the VM is {m.group(2)}, not aarch64")
    need("RINGLET-VM: PREEMPT_RT kernel" in text, "the kernel is not PREEMPT_RT")
    need("vcan" in runs.get("vcan0", ""), "vcan0 did not come up")
    need("RINGLET-VM: done" in text, "the VM did not get to the end of its runs")

    # The limits the runs were given: the configuration the VM used, and the board's timeout.
    hb = re.search(r"^heartbeat_timeout_ms = (\d+)", runs.get("config", ""), re.M)
    bt = re.search(r"RINGLET-VM: board command timeout (\d+) ms", text)
    if not need(hb and bt, "the VM did not say its heartbeat and board timeouts"):
        return report_and_exit(out_dir, results, failures)
    heartbeat_timeout_ms, board_timeout_ms = int(hb.group(1)), int(bt.group(1))
    results["limits_ms"] = {"heartbeat_timeout": heartbeat_timeout_ms, "board_command_timeout": board_timeout_ms}

    check = runs.get("check", "")
    need(exit_status(check) == 0 and "configuration OK" in check, f"ringlet --check failed: {check.strip()[:300]}")

    # ---- the mission through vcan0 ----
    mission_txt = runs.get("mission", "")
    try:
        report = json.loads(runs.get("mission.json", ""))
    except ValueError:
        report = None
    if need(report is not None, f"the mission wrote no report; it said: {mission_txt.strip()[-400:]}"):
        m_ = report["mission"]
        board = m_.get("board") or {}
        rt = board.get("round_trip") or {}
        results["mission"] = {
            "exit": exit_status(mission_txt), "goals_reached": m_["goals_reached"], "goal_count": m_["goal_count"],
            "complete": m_["complete"], "mission_seconds": m_["mission_seconds"], "board_alive": board.get("alive"),
            "frames_received": board.get("frames_received"), "frames_sent": board.get("frames_sent"),
            "malformed": board.get("malformed"), "heartbeat_losses": board.get("heartbeat_losses"),
            "stale_readings": board.get("stale_readings"), "incomplete_scans": board.get("incomplete_scans"),
            "round_trip_ms": {"samples": rt.get("samples", 0), "p50": rt.get("p50_us", 0) / 1e3,
                              "p99": rt.get("p99_us", 0) / 1e3, "max": rt.get("max_us", 0) / 1e3},
            "tasks": {t["name"]: {"budget_us": t["budget_us"], "cpu_p50_us": t["cpu"]["p50_us"],
                                  "cpu_p99_us": t["cpu"]["p99_us"], "overruns": t["overruns"]}
                      for t in report["timing"]["tasks"]},
        }
        need(m_["complete"] and m_["goals_reached"] == m_["goal_count"],
             f"the mission reached {m_['goals_reached']} of {m_['goal_count']} goals")
        need(exit_status(mission_txt) == 0, f"ringlet exited {exit_status(mission_txt)} after the mission")
        need(board.get("malformed") == 0 and board.get("unknown_id") == 0, "malformed or unknown frames on the bus")
        need(rt.get("samples", 0) > 0, "no command -> board -> sensor round trip was measured")
    rt_txt = runs.get("realtime", "")
    # Each thread's name (stat's field 2, in parentheses), real-time priority and policy (1: FIFO).
    fifo = sorted((int(p), name) for name, p, pol in
                  re.findall(r"thread \((\S+)\) rt_priority (\d+) policy (\d+)", rt_txt) if pol == "1")
    lck = re.search(r"VmLck:\s+(\d+) kB", rt_txt)
    results["realtime"] = {"fifo_threads": len(fifo), "priorities": sorted({p for p, _ in fifo}),
                           "fifo": [f"{name} {p}" for p, name in fifo],
                           "locked_kB": int(lck.group(1)) if lck else 0}
    need(fifo == [(50, "ringlet"), (51, "rl-watchdog")],
         "not exactly the cycle's thread at SCHED_FIFO 50 and the watchdog's above it at 51: "
         f"{rt_txt.strip()[:400]}")
    need(lck and int(lck.group(1)) > 0, "the firmware's memory is not locked (VmLck 0)")
    need("not granted" not in mission_txt and "mlockall failed" not in mission_txt,
         "the firmware warned that its real-time settings were refused")
    mb = re.search(r"board done: .*?(\d+) watchdog stops.*?([\d.]+) m driven, (\d+) collisions", runs.get("mission-board", ""))
    if need(mb is not None, "the board printed no summary after the mission"):
        results.setdefault("mission", {})["board_collisions"] = int(mb.group(3))
        results["mission"]["board_distance_m"] = float(mb.group(2))
        need(int(mb.group(3)) == 0, f"the car collided {mb.group(3)} times (the board's count)")

    # ---- the board killed mid-run ----
    frames = can_frames(runs.get("board-killed.can", ""))
    safe = [f for f in frames if f[1] == 0x080]
    if need(safe, "board killed: the firmware sent no CTRL_SAFE_STATE"):
        first = safe[0]
        beats = [f for f in frames if f[1] == 0x180 and f[0] <= first[0]]
        if need(beats, "board killed: no board heartbeat before the safe state"):
            gap_ms = (first[0] - beats[-1][0]) * 1e3
            results["board_killed"] = {"safe_state_after_last_heartbeat_ms": round(gap_ms, 1),
                                       "reason": first[2][0] if first[2] else None,
                                       "limit_ms": heartbeat_timeout_ms + SLACK_MS}
            need(first[2][:1] == b"\x04", f"board killed: safe-state reason {first[2].hex()}, not 4 (heartbeat lost)")
            need(gap_ms <= heartbeat_timeout_ms + SLACK_MS,
                 f"board killed: the safe state came {gap_ms:.1f} ms after the last heartbeat "
                 f"(limit {heartbeat_timeout_ms} + {SLACK_MS} ms)")
        drives_after = [f for f in frames if f[1] == 0x100 and f[0] > first[0] and len(f[2]) >= 6 and f[2][5] == 1]
        need(not drives_after, f"board killed: {len(drives_after)} enabled CTRL_DRIVE frames after the safe state")
    try:
        bk = json.loads(runs.get("board-killed.json", ""))
        need(bk["mission"]["board"]["heartbeat_losses"] >= 1, "board killed: the report counts no heartbeat loss")
    except (ValueError, KeyError, TypeError):
        need(False, f"board killed: no report; the firmware said: {runs.get('board-killed', '').strip()[-300:]}")

    # ---- the firmware killed mid-run ----
    frames = can_frames(runs.get("firmware-killed.can", ""))
    faults = [f for f in frames if f[1] == 0x090 and f[2][:2] == b"\x01\x00"]
    if need(faults, "firmware killed: the board reported no command timeout"):
        fault = faults[0]
        drives = [f for f in frames if f[1] == 0x100 and f[0] <= fault[0]]
        if need(drives, "firmware killed: no CTRL_DRIVE before the board's command timeout"):
            gap_ms = (fault[0] - drives[-1][0]) * 1e3
            results["firmware_killed"] = {"board_stop_after_last_command_ms": round(gap_ms, 1),
                                          "limit_ms": board_timeout_ms + SLACK_MS}
            need(gap_ms <= board_timeout_ms + SLACK_MS,
                 f"firmware killed: the board stopped the car {gap_ms:.1f} ms after the last command "
                 f"(limit {board_timeout_ms} + {SLACK_MS} ms)")
        later = [f for f in frames if f[1] == 0x180 and f[0] > fault[0]]
        need(later and all(len(f[2]) > 1 and f[2][1] == 3 for f in later),
             "firmware killed: the board's heartbeat does not say 'stopped by its watchdog' after the timeout")
    need("1 watchdog stops" in runs.get("firmware-killed-board", ""), "firmware killed: the board counted no watchdog stop")

    return report_and_exit(out_dir, results, failures)


def report_and_exit(out_dir, results, failures):
    out_dir.mkdir(parents=True, exist_ok=True)
    results["failures"] = failures
    (out_dir / "results.json").write_text(json.dumps(results, indent=2) + "\n")
    (out_dir / "results.md").write_text(markdown(results))
    print(markdown(results))
    if failures:
        for f in failures:
            print(f"check.py: FAILED: {f}", file=sys.stderr)
        return 1
    print("check.py: the emulated aarch64 runs passed")
    return 0


def markdown(r):
    m = r.get("mission", {})
    rt = m.get("round_trip_ms", {})
    rt_ = r.get("realtime", {})
    lines = [f"Emulated aarch64 ({r.get('kernel', '?')}, qemu-system-aarch64 TCG, 2 CPUs): function, not timing. "
             f"The firmware ran with {rt_.get('fifo_threads', 0)} SCHED_FIFO thread(s) "
             f"({', '.join(rt_.get('fifo', [])) or '?'}) and {rt_.get('locked_kB', 0)} kB locked.", "",
             "| run | result |", "|---|---|",
             f"| courtyard mission through vcan0 | {m.get('goals_reached', '?')}/{m.get('goal_count', '?')} goals in "
             f"{m.get('mission_seconds', 0):.1f} s, {m.get('board_collisions', '?')} collisions, "
             f"{m.get('board_distance_m', 0):.1f} m; {m.get('frames_received', '?')} frames in, "
             f"{m.get('frames_sent', '?')} out, {m.get('malformed', '?')} malformed, "
             f"{m.get('heartbeat_losses', '?')} heartbeats lost |",
             f"| command → board → sensor round trip (**emulated**) | p50 {rt.get('p50', 0):.2f} ms, "
             f"p99 {rt.get('p99', 0):.2f} ms, max {rt.get('max', 0):.2f} ms over {rt.get('samples', 0)} commands |"]
    bk = r.get("board_killed")
    if bk:
        lines.append(f"| board killed (kill -9) | CTRL_SAFE_STATE reason {bk['reason']} "
                     f"{bk['safe_state_after_last_heartbeat_ms']:.1f} ms after its last heartbeat "
                     f"(limit {bk['limit_ms']} ms) |")
    fk = r.get("firmware_killed")
    if fk:
        lines.append(f"| firmware killed (kill -9) | the board stopped the car "
                     f"{fk['board_stop_after_last_command_ms']:.1f} ms after the last CTRL_DRIVE "
                     f"(limit {fk['limit_ms']} ms) |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.exit(main())
