#!/usr/bin/env bash
# A stop signal sent to a running lockstep binary: it must end in the safe state, print the
# summary, write the report and the picture, record the signal in both, and exit 128 + N.
#   signal_case.sh BIN CONFIG WORKDIR SIGNAL RC [EMULATOR...]      (SIGNAL: INT, TERM, HUP, QUIT)
set -u
bin=$1 config=$2 work=$3 sig=$4 want_rc=$5
shift 5
emulator=("$@")

# shellcheck source=case_lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/case_lib.sh"

rm -rf "$work" && mkdir -p "$work" || exit 1
# Job control: without it bash starts background jobs with SIGINT and SIGQUIT ignored, and ringlet
# keeps a signal ignored that was ignored when it started (the nohup convention).
set -m
# Long enough never to end by itself (the robot stands before a wall); the signal ends it.
"${emulator[@]}" "$bin" --config "$config" --duration 86400 --report "$work/report.json" --svg "$work/run.svg" \
  >"$work/stdout" 2>"$work/stderr" &
pid=$!

# The run has started once it prints its first progress line (after 2 s of host time).
for _ in $(seq 1200); do
  grep -q "ringlet: running:" "$work/stderr" && break
  kill -0 "$pid" 2>/dev/null || fail "the binary ended before it was signalled"
  sleep 0.1
done
grep -q "ringlet: running:" "$work/stderr" || { kill -KILL "$pid"; fail "no progress line within 120 s"; }

kill -"$sig" "$pid" || fail "cannot send SIG$sig"
for _ in $(seq 1200); do
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
if kill -0 "$pid" 2>/dev/null; then kill -KILL "$pid"; fail "still running 120 s after SIG$sig"; fi
wait "$pid"
rc=$?

[[ $rc == "$want_rc" ]] || fail "expected exit code $want_rc after SIG$sig, got $rc"
grep -q "MISSION INTERRUPTED" "$work/stdout" || fail "no 'MISSION INTERRUPTED' summary"
grep -q "safe state forced: yes (SIG$sig)" "$work/stdout" || fail "the summary does not record the safe state and SIG$sig"
grep -q "\"safe_state_forced\": true" "$work/report.json" || fail "report: safe_state_forced is not true"
grep -q "\"safe_state_reason\": \"SIG$sig\"" "$work/report.json" || fail "report: safe_state_reason is not SIG$sig"
grep -q "\"safe_state_at_end\": true" "$work/report.json" || fail "report: safe_state_at_end is not true"
grep -q "\"signal\": \"SIG$sig\"" "$work/report.json" || fail "report: signal is not SIG$sig"
grep -q "</svg>" "$work/run.svg" || fail "no complete picture"
echo "SIG$sig: exit $rc, summary, report and picture record the safe state"
