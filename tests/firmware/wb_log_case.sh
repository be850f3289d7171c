#!/usr/bin/env bash
# ringlet-wb-log on logs the firmware wrote: two lockstep runs with one seed are the same, a third
# with another seed differs and the first differing message is named; `show` filters by type and
# frame; a truncated log, an unknown type and a missing file are refused with exit 2.
#   wb_log_case.sh RINGLET WB_LOG CONFIG WORKDIR [EMULATOR...]
set -u
bin=$1 tool=$2 config=$3 work=$4
shift 4
emulator=("$@")

# shellcheck source=case_lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/case_lib.sh"

rm -rf "$work" && mkdir -p "$work" || exit 1
run() {  # run SEED LOG
  "${emulator[@]}" "$bin" --config "$config" --lockstep --duration 3 --seed "$1" --wb-log "$work/$2" \
    >"$work/stdout" 2>"$work/stderr"
  local rc=$?
  [[ $rc == 0 || $rc == 3 ]] || fail "seed $1: the run ended with exit code $rc"
  [[ -s "$work/$2" ]] || fail "no whiteboard log $2 written"
}
tool() { "${emulator[@]}" "$tool" "$@" >"$work/stdout" 2>"$work/stderr"; }
run 7 a.log
run 7 b.log
run 8 c.log

tool diff "$work/a.log" "$work/b.log"; rc=$?
[[ $rc == 0 ]] || fail "one seed twice: expected exit 0, got $rc"
grep -Eq "^the logs are the same: [0-9]+ messages over (29[0-9]|30[0-9]) frames$" "$work/stdout" ||
  fail "the same logs are not reported as such"

tool diff "$work/a.log" "$work/c.log"; rc=$?
[[ $rc == 1 ]] || fail "two seeds: expected exit 1, got $rc"
grep -Eq "^the logs differ: message [0-9]+: expected [A-Za-z]+ generation [0-9]+ \(frame [0-9]+\): .*; got " "$work/stdout" ||
  fail "the first difference is not named"

tool show "$work/a.log" --type MotionCommand --from 10 --to 19; rc=$?
[[ $rc == 0 ]] || fail "show: expected exit 0, got $rc"
lines=$(grep -c "^MotionCommand generation [0-9]* (frame 1[0-9]): " "$work/stdout")
others=$(grep -vc "^MotionCommand generation [0-9]* (frame 1[0-9]): \|^[0-9]* messages$" "$work/stdout")
[[ $lines -ge 10 && $others == 0 ]] || fail "show --type --from --to: $lines matching lines, $others others"

head -c 5000 "$work/a.log" >"$work/cut.log"
tool show "$work/cut.log"; rc=$?
[[ $rc == 2 ]] || fail "a truncated log: expected exit 2, got $rc"
grep -q "$work/cut.log: .* at byte [0-9]*" "$work/stderr" || fail "the truncated log's error names no file and byte"

tool diff "$work/a.log" "$work/b.log" --type NoSuchType; rc=$?
[[ $rc == 2 ]] && grep -q "no whiteboard type named 'NoSuchType'" "$work/stderr" || fail "an unknown type is not refused"

tool show "$work/missing.log"; rc=$?
[[ $rc == 2 ]] && grep -q "$work/missing.log" "$work/stderr" || fail "a missing log is not refused by name"
echo "ringlet-wb-log: same, differing, filtered and bad logs as expected"
