#!/usr/bin/env python3
"""Runs llfsmc on every model in models/bad/ and checks its exact error output.

Each bad model states what it expects in `# expect: <file>:<line>: <message>` lines; the
generator must print exactly those lines on stderr, nothing on stdout, and exit with status 1.
The good models in models/ must compile silently with status 0.
usage: llfsmc_errors_test.py <llfsmc.py> <models dir>
"""
import glob
import os
import subprocess
import sys


def run(gen, model_dir, name):
    return subprocess.run([sys.executable, gen, name], cwd=model_dir, capture_output=True, text=True)


def main():
    gen, models = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    failures = 0
    bad_dir = os.path.join(models, "bad")
    bad = sorted(glob.glob(os.path.join(bad_dir, "*.machine")))
    for path in bad:
        name = os.path.basename(path)
        with open(path, encoding="utf-8") as f:
            expected = [l[len("# expect: "):].rstrip("\n") for l in f if l.startswith("# expect: ")]
        r = run(gen, bad_dir, name)
        got = r.stderr.splitlines()
        if r.returncode != 1 or got != expected or r.stdout:
            failures += 1
            print(f"FAIL {name}: exit {r.returncode}\n  expected: {expected}\n  got:      {got}")
        else:
            print(f"ok   {name}: {got[0]}")
    for path in sorted(glob.glob(os.path.join(models, "*.machine"))):
        name = os.path.basename(path)
        r = run(gen, models, name)
        if r.returncode != 0 or r.stderr:
            failures += 1
            print(f"FAIL {name}: good model rejected (exit {r.returncode}): {r.stderr}")
        else:
            print(f"ok   {name}: accepted")
    if not bad:
        print("FAIL: no bad models found")
        failures += 1
    print(f"{failures} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
