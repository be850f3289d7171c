# Shared by the shell test cases (signal_case.sh, output_failure_case.sh, camera_module_case.sh): `fail MESSAGE` prints
# the message and what the binary printed (from $work/stdout and $work/stderr), then exits 1.
fail() {
  echo "FAIL: $*"
  echo "--- stdout"; cat "$work/stdout" 2>/dev/null
  echo "--- stderr (first 60 lines)"; head -n 60 "$work/stderr" 2>/dev/null
  exit 1
}
