#!/usr/bin/env bash
# Model-checks every shipped machine and schedule with spin (behaviour/llfsmc/spin_verify.py) and
# prints the figures as the Markdown table behaviour/README.md shows ("Model checking"). The
# ringlets per turn are the firmware's (Safety 2, the others 1); PlanExecute alone runs with 500 ms
# turns (its model file says why). Work files go to $1 (default a
# temporary directory). The same runs are the ctest tests SpinVerify.*.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
WORK="${1:-$(mktemp -d)}"
echo "| model | property | holds | states | depth | pan time (s) |"
echo "|---|---|---|---:|---:|---:|"
for model in "$ROOT"/behaviour/machines/*.machine "$ROOT"/behaviour/machines/*.schedule; do
  name="$(basename "$model")"
  extra=()
  [[ "$name" == safety.machine ]] && extra=(--ringlets 2)
  [[ "$name" == plan_execute.machine ]] && extra=(--period-ms 500)  # as SpinVerify.plan_execute
  python3 -B "$ROOT/behaviour/llfsmc/spin_verify.py" "$model" --work "$WORK/$name" "${extra[@]}" |
    sed -nE "s/^(HOLDS|FAILS) ([^ :]+)[^:]*: ([0-9]+) states, depth ([0-9]+), ([0-9.]+) s \(pan\).*/| $name | \2 | \1 | \3 | \4 | \5 |/p"
done
