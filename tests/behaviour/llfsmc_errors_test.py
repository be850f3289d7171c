#!/usr/bin/env python3
"""Runs llfsmc on every model in models/bad/ and checks its exact error output.

Each bad model states what it expects in `# expect: <file>:<line>:<col>: error: <message>` lines;
the generator must print exactly those lines on stderr, nothing on stdout, and exit with status 1.
The good models in models/ must compile silently with status 0.
usage: llfsmc_errors_test.py <llfsmc.py> <models dir>
"""
import glob
import os
import subprocess
import sys

PREFIX = b"# expect: "


def run(gen, model_dir, name):
    return subprocess.run([sys.executable, gen, name], cwd=model_dir, capture_output=True)


def well_formed(line, name):
    """`name:LINE:COL: error: message` with numbers, or `name: error: message`."""
    head, sep, message = line.partition(": error: ")
    if not sep or not message:
        return False
    parts = head.split(":")
    return parts[0] == name and (len(parts) == 1 or (len(parts) == 3 and all(p.isdigit() for p in parts[1:])))


def main():
    gen, models = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    failures = 0
    bad_dir = os.path.join(models, "bad")
    bad = sorted(glob.glob(os.path.join(bad_dir, "*.machine")))
    for path in bad:
        name = os.path.basename(path)
        with open(path, "rb") as f:  # bytes: one of the bad models is not UTF-8 on purpose
            expected = [l[len(PREFIX):].rstrip(b"\n").decode("utf-8") for l in f if l.startswith(PREFIX)]
        r = run(gen, bad_dir, name)
        got = r.stderr.decode("utf-8", "replace").splitlines()
        if r.returncode != 1 or got != expected or r.stdout or not expected \
                or not all(well_formed(l, name) for l in got):
            failures += 1
            print(f"FAIL {name}: exit {r.returncode}\n  expected: {expected}\n  got:      {got}")
        else:
            print(f"ok   {name}: {got[0]}")
    for path in sorted(glob.glob(os.path.join(models, "*.machine"))):
        name = os.path.basename(path)
        r = run(gen, models, name)
        if r.returncode != 0 or r.stderr:
            failures += 1
            print(f"FAIL {name}: good model rejected (exit {r.returncode}): {r.stderr.decode('utf-8', 'replace')}")
        else:
            print(f"ok   {name}: accepted")
    if not bad:
        print("FAIL: no bad models found")
        failures += 1
    print(f"{failures} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
