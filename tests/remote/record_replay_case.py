#!/usr/bin/env python3
"""ringlet-monitor record, replay and --plotjuggler against two firmware processes.

    record_replay_case.py --emulator "<emu>" --ringlet R --monitor M --config6 C6 --config8 C8 --partition P

1. One monitor records two robots (6 and 8: two firmware processes, lockstep, each waiting for the
   monitor) until both runs end: the file holds both robots, told apart, every FsmStatus of each
   in generation order, and each robot's BridgeHealth.
2. The recording is replayed into another partition (as fast as possible) while `echo FsmStatus
   --robot 8 --json` listens there: it receives robot 8's FsmStatus samples as recorded, in order.
3. While it is replayed again, `--plotjuggler 127.0.0.1:PORT` streams to a UDP socket here: the
   datagrams are JSON objects with a timestamp and /robot8/FsmStatus/<machine>/ringlets.
Exit 0 when all hold.
"""
import argparse
import json
import os
import shlex
import signal
import socket
import subprocess
import sys
import tempfile
import time


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, **kw)


def main():
    ap = argparse.ArgumentParser()
    for a in ("--emulator", "--ringlet", "--monitor", "--config6", "--config8", "--partition"):
        ap.add_argument(a, default="")
    a = ap.parse_args()
    emu = shlex.split(a.emulator)
    mon = emu + [a.monitor, "--partition", a.partition]
    out = tempfile.mkdtemp(prefix="ringlet-record-")
    rec = os.path.join(out, "match.jsonl")
    failures = []

    # 1. Record two robots.
    recorder = subprocess.Popen(mon + ["record", rec, "--wait", "240"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    runs = [subprocess.Popen(emu + [a.ringlet, "--config", c, "--lockstep", "--duration", "3"], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True) for c in (a.config6, a.config8)]
    for r in runs:
        r.communicate(timeout=240)
    time.sleep(1.0)  # the last samples on their way
    recorder.send_signal(signal.SIGINT)
    rec_out, rec_err = recorder.communicate(timeout=60)
    if recorder.returncode != 0:
        print(f"record exit {recorder.returncode}: {rec_out} {rec_err}")
        return 1
    with open(rec) as f:
        lines = [json.loads(line) for line in f]
    header, samples = lines[0], lines[1:]
    if header.get("ringlet_record") != 1 or header.get("partition") != a.partition:
        failures.append(f"header: {header}")
    robots = sorted({s["robot"] for s in samples})
    if robots != [6, 8]:
        failures.append(f"robots recorded: {robots}, expected [6, 8]")
    status = {}
    for s in samples:
        if s["type"] == "FsmStatus":
            status.setdefault((s["robot"], s["fields"]["machine"]), []).append(s["generation"])
    for robot in (6, 8):
        for machine in ("BallTracker", "Mission", "Safety"):
            gens = status.get((robot, machine), [])
            if not gens:
                failures.append(f"no FsmStatus of robot {robot}'s {machine}")
            elif gens != sorted(gens) or len(set(gens)) != len(gens):
                failures.append(f"robot {robot}'s {machine} FsmStatus generations out of order")
        if not any(s["type"] == "BridgeHealth" and s["robot"] == robot for s in samples):
            failures.append(f"no BridgeHealth of robot {robot}")
    robot8 = [(s["fields"]["machine"], s["fields"]["state"], s["fields"]["ringlets"]) for s in samples
              if s["type"] == "FsmStatus" and s["robot"] == 8]
    print(f"recorded {len(samples)} samples of robots {robots}; robot 8: {len(robot8)} FsmStatus")

    # 2. Replay into another partition; echo there hears robot 8's FsmStatus as recorded.
    other = emu + [a.monitor, "--partition", a.partition + "-replay"]
    echo = subprocess.Popen(other + ["--robot", "8", "echo", "FsmStatus", "--json", "-n", str(len(robot8)), "--wait", "120"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(0.5)
    replay = run(other + ["replay", rec, "--speed", "0", "--wait", "30"], timeout=240)
    echo_out, echo_err = echo.communicate(timeout=240)
    heard = [(j["fields"]["machine"], j["fields"]["state"], j["fields"]["ringlets"]) for j in map(json.loads, echo_out.splitlines())]

    # DDS orders samples per instance (per machine), not across machines: compare each machine's.
    def per_machine(seq):
        out = {}
        for machine, state, ringlets in seq:
            out.setdefault(machine, []).append((state, ringlets))
        return out
    if replay.returncode != 0 or f"replayed {len(samples)} of {len(samples)} samples" not in replay.stdout:
        failures.append(f"replay: exit {replay.returncode}: {replay.stdout} {replay.stderr}")
    if per_machine(heard) != per_machine(robot8):
        failures.append(f"echo of the replay heard {len(heard)} FsmStatus of robot 8, recorded {len(robot8)}"
                        + ("" if len(heard) != len(robot8) else " (different values)") + f"; echo: {echo_err}")

    # 3. --plotjuggler while it is replayed again.
    udp = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    udp.bind(("127.0.0.1", 0))
    udp.settimeout(0.2)
    port = udp.getsockname()[1]
    stream = subprocess.Popen(other + ["--plotjuggler", f"127.0.0.1:{port}", "--wait", "60"], stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True)
    time.sleep(0.5)
    replay2 = subprocess.Popen(other + ["replay", rec, "--speed", "0", "--wait", "30"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    found = None
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and found is None:
        try:
            d = json.loads(udp.recv(65536))
        except socket.timeout:
            continue
        fsm = d.get("robot8", {}).get("FsmStatus", {})
        if "timestamp" in d and any(isinstance(v, dict) and "ringlets" in v for v in fsm.values()):
            found = d
    replay2.communicate(timeout=240)
    stream.send_signal(signal.SIGINT)
    stream.communicate(timeout=60)
    if found is None:
        failures.append("no PlotJuggler datagram with /robot8/FsmStatus/<machine>/ringlets")
    else:
        print(f"plotjuggler datagram: {json.dumps(found)[:160]}")

    for f in failures:
        print("FAILED:", f)
    if not failures:
        print(f"record/replay case passed: robots 6 and 8 recorded by one monitor, {len(robot8)} FsmStatus of robot 8 "
              f"replayed and heard in order, PlotJuggler JSON received")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
