#!/usr/bin/env bash
# One output that cannot be written at the end must not cost the other: the report's folder is
# removed while a real-time run is going; the picture must still be written, the failure named,
# and the exit code 1.
#   output_failure_case.sh BIN CONFIG WORKDIR [EMULATOR...]
set -u
bin=$1 config=$2 work=$3
shift 3
emulator=("$@")

# shellcheck source=case_lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/case_lib.sh"

rm -rf "$work" && mkdir -p "$work/vanishing" || exit 1
"${emulator[@]}" "$bin" --config "$config" --realtime --duration 4 --report "$work/vanishing/report.json" \
  --svg "$work/run.svg" >"$work/stdout" 2>"$work/stderr" &
pid=$!
for _ in $(seq 1200); do
  grep -q "ringlet: running:" "$work/stderr" && break
  kill -0 "$pid" 2>/dev/null || fail "the binary ended before the folder was removed"
  sleep 0.1
done
rm -rf "$work/vanishing"
wait "$pid"
rc=$?

[[ $rc == 1 ]] || fail "expected exit code 1, got $rc"
grep -q -- "--report $work/vanishing/report.json: cannot write the report" "$work/stderr" || fail "the failure is not named"
grep -q "</svg>" "$work/run.svg" || fail "the picture was not written"
grep -q "picture: $work/run.svg" "$work/stdout" || fail "the picture is not reported"
echo "report failed as expected (exit 1); the picture was written"
