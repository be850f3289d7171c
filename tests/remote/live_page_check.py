#!/usr/bin/env python3
"""Loads ringlet-monitor's live page in headless Chromium and checks that it is live.

    live_page_check.py --chromium chromium --url http://127.0.0.1:PORT/ [--timeout 60] [--screenshot page.png]

Chromium is driven over its DevTools protocol (python3-websocket): the page is read as it updates,
which a one-shot --dump-dom cannot do with a server-sent-events stream open. Passes when, within
--timeout seconds, the page shows
  - a pose (x, y, heading) that changes while it is watched: the robot drives and the page follows;
  - a machine state change that happens while it is watched (a transition not on the page at first);
  - a highlighted state in a machine diagram, and a timing table with rows.
Exit 0 when all hold, 1 when one does not (the last page state is printed), 2 when Chromium cannot
be started.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import urllib.request

try:
    import websocket  # Debian python3-websocket
except ImportError:
    sys.exit("live_page_check: the Python module websocket is missing (Debian python3-websocket; tools/ringlet setup installs it)")

# What the page shows, read in the page.
PROBE = """JSON.stringify({
  status: document.getElementById('status').textContent,
  pose: document.getElementById('pose').textContent,
  transitions: [...document.querySelectorAll('#transitions li')].map(li => li.textContent),
  current: [...document.querySelectorAll('.diagram g.node.current title')].map(t => t.textContent),
  diagrams: document.querySelectorAll('.diagram').length,
  timing_rows: document.querySelectorAll('#timing tbody tr').length,
  machines: [...document.querySelectorAll('#machines tbody tr')].map(tr => tr.textContent),
})"""


class DevTools:
    def __init__(self, ws_url):
        self.ws = websocket.create_connection(ws_url, timeout=30)
        self.next_id = 0

    def call(self, method, **params):
        self.next_id += 1
        self.ws.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        while True:
            reply = json.loads(self.ws.recv())
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})

    def page_state(self):
        """What the page shows, or None while it is still loading (the probe throws on a page
        without the elements, e.g. about:blank before the navigation)."""
        r = self.call("Runtime.evaluate", expression=PROBE, returnByValue=True)
        if "exceptionDetails" in r or "value" not in r.get("result", {}):
            return None
        return json.loads(r["result"]["value"])


def start_chromium(chromium, url, width, height, profile):
    args = [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-extensions",
            f"--user-data-dir={profile}", "--remote-debugging-port=0", f"--window-size={width},{height}",
            "--hide-scrollbars", url]
    proc = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        line = proc.stderr.readline()
        if not line:
            if proc.poll() is not None:
                break
            continue
        m = re.search(r"DevTools listening on ws://([^/]+)/", line)
        if m:
            return proc, m.group(1)
    proc.kill()
    sys.stderr.write("live_page_check: Chromium did not start (no DevTools endpoint)\n")
    sys.exit(2)


def page_target(host):
    for _ in range(100):
        with urllib.request.urlopen(f"http://{host}/json/list") as r:
            pages = [t for t in json.load(r) if t.get("type") == "page"]
        if pages:
            return pages[0]["webSocketDebuggerUrl"]
        time.sleep(0.1)
    sys.exit("live_page_check: Chromium shows no page")


POSE = re.compile(r"x (-?\d+\.\d+) m · y (-?\d+\.\d+) m · heading (-?\d+\.\d+)°")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--chromium", default=shutil.which("chromium") or "chromium")
    ap.add_argument("--url", required=True)
    ap.add_argument("--timeout", type=float, default=60.0, help="seconds to wait for everything (default 60)")
    ap.add_argument("--screenshot", help="also write the page as PNG here once it passed")
    ap.add_argument("--settle", type=float, default=0.0, help="seconds to let the run go on before the screenshot")
    ap.add_argument("--width", type=int, default=1600)
    ap.add_argument("--height", type=int, default=1000)
    a = ap.parse_args()

    profile = tempfile.mkdtemp(prefix="ringlet-chromium-")
    proc, host = start_chromium(a.chromium, a.url, a.width, a.height, profile)
    try:
        tools = DevTools(page_target(host))
        deadline = time.monotonic() + a.timeout
        first = None       # the first page state with a pose
        state = {}
        got = {}
        while time.monotonic() < deadline:
            time.sleep(0.25)
            now = tools.page_state()
            if now is None:
                continue
            state = now
            pose = POSE.search(state["pose"])
            if not pose:
                continue
            if first is None:
                first = state
                first_pose = pose.groups()
                continue
            got["pose"] = True
            got["pose moves"] = got.get("pose moves") or pose.groups() != first_pose
            got["state change"] = got.get("state change") or any(t not in first["transitions"] for t in state["transitions"])
            got["diagram highlight"] = len(state["current"]) > 0
            got["timing table"] = state["timing_rows"] > 0
            if len(got) == 5 and all(got.values()):
                break
        ok = len(got) == 5 and all(got.values())
        print(json.dumps({"checks": got, "page": state}, ensure_ascii=False, indent=1))
        if ok and a.screenshot:
            time.sleep(a.settle)
            shot = tools.call("Page.captureScreenshot", format="png")
            import base64
            with open(a.screenshot, "wb") as f:
                f.write(base64.b64decode(shot["data"]))
            print(f"screenshot: {a.screenshot}")
        if ok:
            print("live page check passed: pose shown and moving, a state change seen live, a diagram state highlighted, timing table filled")
            return 0
        missing = [k for k in ("pose", "pose moves", "state change", "diagram highlight", "timing table") if not got.get(k)]
        print(f"live page check FAILED within {a.timeout} s: not seen: {', '.join(missing)}")
        return 1
    finally:
        proc.kill()
        proc.wait()
        shutil.rmtree(profile, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
