#!/bin/sh
# ringlet-monitor against a real firmware run, two processes on loopback:
#   monitor_case.sh "<emulator>" <ringlet> <ringlet-monitor> <config> <partition>
# The firmware (lockstep, [remote] wait_for_monitors = 1) waits for the monitor, runs 3 s of the
# courtyard mission and ends; `ringlet-monitor echo FsmStatus --json` must print every machine's
# status lines, `fsm --once` the table with all three machines, and `control` suspend a machine.
set -u
emu=$1 ringlet=$2 monitor=$3 config=$4 partition=$5
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
$emu "$monitor" --partition "$partition" echo FsmStatus --json -n 40 --wait 120 > "$out/echo.txt" 2> "$out/echo.err" &
echo_pid=$!
$emu "$ringlet" --config "$config" --lockstep --duration 3 > "$out/run.txt" 2>&1
run_rc=$?
wait $echo_pid
echo_rc=$?
# A late monitor: the run is over, but the states are transient-local only while the robot lives,
# so the table is taken from a second run.
$emu "$monitor" --partition "$partition" fsm --once --wait 60 > "$out/fsm.txt" 2> "$out/fsm.err" &
fsm_pid=$!
$emu "$ringlet" --config "$config" --lockstep --duration 3 > "$out/run2.txt" 2>&1
wait $fsm_pid
fsm_rc=$?
# Remote control: the robot (20 s of lockstep) waits for the monitor, which asks it to suspend
# BallTracker and waits until the robot's FsmStatus shows it.
$emu "$ringlet" --config "$config" --lockstep --duration 20 > "$out/run3.txt" 2>&1 &
run3_pid=$!
$emu "$monitor" --partition "$partition" --robot 6 control BallTracker suspend --wait 120 > "$out/control.txt" 2> "$out/control.err"
control_rc=$?
wait $run3_pid
fail=0
[ "$control_rc" = 0 ] && grep -q "robot 6: BallTracker suspended" "$out/control.txt" \
  || { echo "control exit $control_rc:"; cat "$out/control.txt" "$out/control.err"; fail=1; }
grep -q "machine BallTracker .*(suspended)" "$out/run3.txt" && grep -q "remote writes: 1 accepted" "$out/run3.txt" \
  || { echo "the run does not end with BallTracker suspended by 1 accepted remote write:"; tail -12 "$out/run3.txt"; fail=1; }
[ "$run_rc" = 3 ] || { echo "firmware exit $run_rc (expected 3: a 3 s run is incomplete)"; cat "$out/run.txt"; fail=1; }
[ "$echo_rc" = 0 ] || { echo "echo exit $echo_rc"; cat "$out/echo.err"; fail=1; }
[ "$(wc -l < "$out/echo.txt")" -eq 40 ] || { echo "echo printed $(wc -l < "$out/echo.txt") lines, expected 40"; fail=1; }
grep -q '"type":"FsmStatus"' "$out/echo.txt" && grep -q '"robot":6' "$out/echo.txt" && grep -q '"machine":"Safety"' "$out/echo.txt" \
  || { echo "echo lines lack the type, robot 6 or Safety:"; head -5 "$out/echo.txt"; fail=1; }
[ "$fsm_rc" = 0 ] || { echo "fsm exit $fsm_rc"; cat "$out/fsm.err"; fail=1; }
for m in BallTracker Mission Safety; do
  grep -q "^6  *$m " "$out/fsm.txt" || { echo "fsm table lacks robot 6's $m:"; cat "$out/fsm.txt"; fail=1; }
done
grep -q "remote: robot 6 on DDS domain 0" "$out/run.txt" || { echo "no remote line in the report:"; tail -5 "$out/run.txt"; fail=1; }
[ $fail = 0 ] && echo "monitor case passed: 40 FsmStatus echoed as JSON, the fsm table has robot 6's three machines, control suspended BallTracker"
exit $fail
