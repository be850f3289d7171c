#!/bin/sh
# The live page of a running simulation, in headless Chromium:
#   live_page_case.sh "<emulator>" <ringlet> <ringlet-monitor> <config> <partition> <python3> <chromium> [screenshot.png [settle_s [clock]]]
# ringlet-monitor serve (any free port) listens; the firmware runs the courtyard mission on the
# real clock with [remote] on (and waits for the monitor); live_page_check.py loads the page in
# Chromium and checks that the pose moves and a machine's state changes while it watches.
# clock: --realtime (the test) or --lockstep (a run whose picture does not depend on the host's
# load, paced by the monitor's acknowledgements: tools/ringlet page-shot).
set -u
emu=$1 ringlet=$2 monitor=$3 config=$4 partition=$5 python=$6 chromium=$7 shot=${8:-} settle=${9:-0} clock=${10:---realtime}
out=$(mktemp -d)
serve_pid= run_pid=
cleanup() {
  [ -n "$run_pid" ] && kill "$run_pid" 2>/dev/null
  [ -n "$serve_pid" ] && kill "$serve_pid" 2>/dev/null
  wait 2>/dev/null
  rm -rf "$out"
}
trap cleanup EXIT
if ! command -v "$chromium" >/dev/null 2>&1; then
  echo "live page case: Chromium ($chromium) is not installed: run tools/ringlet setup (Debian chromium)"
  exit 1
fi
$emu "$monitor" --partition "$partition" serve --port 0 > "$out/serve.txt" 2> "$out/serve.err" &
serve_pid=$!
url=
for _ in $(seq 1 300); do
  url=$(grep -o 'http://[0-9.]*:[0-9]*/' "$out/serve.txt" 2>/dev/null | head -1)
  [ -n "$url" ] && break
  kill -0 "$serve_pid" 2>/dev/null || break
  sleep 0.1
done
if [ -z "$url" ]; then
  echo "live page case: ringlet-monitor serve did not start:"; cat "$out/serve.txt" "$out/serve.err"; exit 1
fi
$emu "$ringlet" --config "$config" "$clock" --duration 60 > "$out/run.txt" 2>&1 &
run_pid=$!
if [ -n "$shot" ]; then
  "$python" "$(dirname "$0")/live_page_check.py" --chromium "$chromium" --url "$url" --timeout 90 --screenshot "$shot" --settle "$settle" > "$out/check.txt" 2>&1
else
  "$python" "$(dirname "$0")/live_page_check.py" --chromium "$chromium" --url "$url" --timeout 90 > "$out/check.txt" 2>&1
fi
rc=$?
tail -1 "$out/check.txt"
if [ $rc != 0 ]; then
  cat "$out/check.txt"
  echo "--- firmware:"; tail -8 "$out/run.txt"
  echo "--- serve:"; cat "$out/serve.txt" "$out/serve.err"
fi
exit $rc
