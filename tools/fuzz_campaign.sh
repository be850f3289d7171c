#!/usr/bin/env bash
# A long fuzzing campaign: each target in turn (one process at a time, niced so the machine stays
# usable), from its committed seed corpus, for a fixed number of executions; then a table of the
# figures tests/fuzz/README.md records (executions, exec/s, final cov/ft, corpus, crashes).
#
#   tools/fuzz_campaign.sh [--runs N] [--no-build] [TARGET...]     (no TARGET: all of them)
#
# Targets are the ringlet_fuzz_<name> programs of the fuzz preset (build/fuzz/tests/fuzz). Each
# run starts from an empty scratch corpus plus the committed one (only read), -seed=1, with the
# target's dictionary when there is one. Logs, the grown corpus and any reproducer go to
# build/fuzz/campaign/<name>/. Exits 1 if any target crashed (or failed otherwise).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

RUNS=1000000
BUILD=1
FUZZ_DIR="build/fuzz/tests/fuzz"
SRC_DIR="tests/fuzz"
OUT_DIR="build/fuzz/campaign"

usage() {
  sed -n '2,11p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
}

targets=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --runs)
      [[ $# -ge 2 && "$2" =~ ^[1-9][0-9]*$ ]] || { echo "fuzz_campaign: --runs needs a positive integer" >&2; exit 2; }
      RUNS="$2"; shift 2 ;;
    --no-build) BUILD=0; shift ;;
    -h|--help) usage; exit 0 ;;
    -*) echo "fuzz_campaign: unknown option $1" >&2; usage >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done

if [[ $BUILD -eq 1 ]]; then
  cmake --preset fuzz >/dev/null
  cmake --build --preset fuzz -j"${RINGLET_JOBS:-2}"
fi

if [[ ${#targets[@]} -eq 0 ]]; then
  for bin in "$FUZZ_DIR"/ringlet_fuzz_*; do
    name="${bin##*/ringlet_fuzz_}"
    [[ -d "$SRC_DIR/corpus/$name" ]] && targets+=("$name")
  done
fi
[[ ${#targets[@]} -gt 0 ]] || { echo "fuzz_campaign: no fuzz targets in $FUZZ_DIR (build the fuzz preset)" >&2; exit 2; }

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

rows=()
failed=0
for name in "${targets[@]}"; do
  bin="$FUZZ_DIR/ringlet_fuzz_$name"
  seeds="$SRC_DIR/corpus/$name"
  [[ -x "$bin" ]] || { echo "fuzz_campaign: $bin not built" >&2; exit 2; }
  [[ -d "$seeds" ]] || { echo "fuzz_campaign: no seed corpus $seeds" >&2; exit 2; }
  work="$OUT_DIR/$name"
  rm -rf "$work"
  mkdir -p "$work/corpus" "$work/artifacts"
  args=(-seed=1 -runs="$RUNS" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1
        -artifact_prefix="$work/artifacts/")
  [[ -f "$SRC_DIR/$name.dict" ]] && args+=(-dict="$SRC_DIR/$name.dict")
  # Per-target campaign flags (one libFuzzer flag a line, e.g. -max_len), in tests/fuzz/NAME.args.
  if [[ -f "$SRC_DIR/$name.args" ]]; then
    while IFS= read -r flag; do
      if [[ -n "$flag" && "$flag" != \#* ]]; then args+=("$flag"); fi
    done <"$SRC_DIR/$name.args"
  fi
  cmd=(nice -n 19 "$bin" "${args[@]}" "$work/corpus" "$seeds")
  echo "fuzz_campaign: ${cmd[*]}" | tee "$work/command.txt"
  start=$SECONDS
  rc=0
  "${cmd[@]}" >"$work/fuzz.log" 2>&1 || rc=$?
  took=$((SECONDS - start))

  # The last status line ("#N DONE cov: C ft: F corp: K/S ...") and the final stats.
  status="$(grep -E '^#[0-9]+.*cov: ' "$work/fuzz.log" | tail -n 1 || true)"
  cov="$(sed -nE 's/.* cov: ([0-9]+).*/\1/p' <<<"$status")"
  ft="$(sed -nE 's/.* ft: ([0-9]+).*/\1/p' <<<"$status")"
  corp="$(sed -nE 's/.* corp: ([0-9]+\/[0-9]+[A-Za-z]*).*/\1/p' <<<"$status")"
  execs="$(sed -nE 's/^stat::number_of_executed_units: *([0-9]+).*/\1/p' "$work/fuzz.log")"
  eps="$(sed -nE 's/^stat::average_exec_per_sec: *([0-9]+).*/\1/p' "$work/fuzz.log")"
  corpus_files="$(find "$work/corpus" -type f | wc -l)"
  corpus_bytes="$(find "$work/corpus" -type f -printf '%s\n' | awk '{ n += $1 } END { print n + 0 }')"
  crashes="$(find "$work/artifacts" -type f | wc -l)"
  if [[ $rc -ne 0 || $crashes -ne 0 ]]; then
    failed=$((failed + 1))
    echo "fuzz_campaign: $name FAILED (exit $rc); reproducers in $work/artifacts; log $work/fuzz.log" >&2
  fi
  rows+=("$(printf '%-10s %10s %8s %6s %7s %13s %12s %7s %6ss' "$name" "${execs:-?}" "${eps:-?}" "${cov:-?}" \
            "${ft:-?}" "${corp:-?}" "$corpus_files/${corpus_bytes}b" "$crashes" "$took")")
done

echo
echo "fuzz campaign: -runs=$RUNS -seed=1, one target at a time (nice 19)"
echo "(corp: libFuzzer's final in-memory corpus, entries/bytes; new: files it wrote, i.e. inputs"
echo " with new coverage beyond the seeds, before libFuzzer's reductions replace some in memory)"
printf '%-10s %10s %8s %6s %7s %13s %12s %7s %7s\n' target execs exec/s cov ft corp new crashes time
for r in "${rows[@]}"; do echo "$r"; done
[[ $failed -eq 0 ]]
