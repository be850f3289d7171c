#!/usr/bin/env bash
# Runs each configuration N times in lockstep beside a CPU hog (busy loops), and counts
# the distinct (trajectory hash, run hash) pairs: a lockstep run is a pure function of seed and
# configuration, so each configuration must give exactly one. Prints a progress line per run and
# a table at the end; exits 1 if any configuration gave more than one pair.
#
#   tools/determinism_check.sh [-n RUNS] [--hog N | --no-hog] [--bin PATH] [CONFIG...]
#
# Defaults: 100 runs of each shipped configuration (firmware/config/*.toml) with the release
# binary (build it first: cmake --preset release && cmake --build --preset release), beside a hog
# of one busy loop per core (--hog N: N loops).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
RUNS=100
HOG="$(nproc)"
BIN="$ROOT/build/release/firmware/ringlet"
CONFIGS=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    -n) RUNS="${2:?-n needs a number}"; shift 2 ;;
    --no-hog) HOG=0; shift ;;
    --hog) HOG="${2:?--hog needs a number}"; shift 2 ;;
    --bin) BIN="${2:?--bin needs a path}"; shift 2 ;;
    -h|--help) sed -n '2,11p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "determinism_check: unknown option $1" >&2; exit 2 ;;
    *) CONFIGS+=("$1"); shift ;;
  esac
done
[[ "$RUNS" =~ ^[1-9][0-9]*$ ]] || { echo "determinism_check: -n must be a positive integer, not '$RUNS'" >&2; exit 2; }
[[ "$HOG" =~ ^[0-9]+$ ]] || { echo "determinism_check: --hog must be a number of loops, not '$HOG'" >&2; exit 2; }
[[ -x "$BIN" ]] || { echo "determinism_check: $BIN not built (cmake --build --preset release)" >&2; exit 2; }
if [[ ${#CONFIGS[@]} -eq 0 ]]; then CONFIGS=("$ROOT"/firmware/config/*.toml); fi

TMP="$(mktemp -d)"
HOG_PIDS=()
cleanup() {
  for p in "${HOG_PIDS[@]}"; do kill "$p" 2>/dev/null || true; done
  rm -rf "$TMP"
}
trap cleanup EXIT
if [[ $HOG -gt 0 ]]; then
  for _ in $(seq "$HOG"); do
    ( while :; do :; done ) &
    HOG_PIDS+=($!)
  done
  echo "CPU hog: ${#HOG_PIDS[@]} busy shell loops (one per core)"
fi

failed=0
summary=()
for cfg in "${CONFIGS[@]}"; do
  : >"$TMP/hashes"
  for i in $(seq "$RUNS"); do
    rc=0
    "$BIN" --config "$cfg" --report "$TMP/r.json" >"$TMP/log" 2>&1 || rc=$?
    python3 - "$TMP/r.json" "$rc" >>"$TMP/hashes" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))["mission"]
print(m["trajectory_hash"], m["run_hash"], "exit", sys.argv[2])
PY
    printf '\r%s: run %d/%d' "$(basename "$cfg")" "$i" "$RUNS"
  done
  echo
  distinct="$(sort "$TMP/hashes" | uniq -c)"
  n="$(wc -l <<<"$distinct")"
  echo "$distinct" | sed 's/^/    /'
  summary+=("$(printf '%-18s %4d runs  %d distinct (trajectory, run) hash pair(s)' "$(basename "$cfg")" "$RUNS" "$n")")
  [[ "$n" -eq 1 ]] || failed=1
done
echo
printf '%s\n' "${summary[@]}"
exit "$failed"
