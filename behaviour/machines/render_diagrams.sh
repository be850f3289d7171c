#!/usr/bin/env bash
# Regenerates docs/machines/<model>.dot from every behaviour/machines/*.machine and, if Graphviz
# `dot` is installed, <model>.svg next to it. Run by hand after editing a model and commit the
# results: the build does not need Graphviz (ctest MachineDiagramUpToDate.* fails on a stale .dot).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
OUT="$ROOT/docs/machines"
mkdir -p "$OUT"
for model in "$ROOT"/behaviour/machines/*.machine; do
  stem="$(basename "$model" .machine)"
  python3 "$ROOT/behaviour/llfsmc/llfsmc.py" "$model" --dot "$OUT/$stem.dot"
  if command -v dot >/dev/null 2>&1; then
    dot -Tsvg "$OUT/$stem.dot" -o "$OUT/$stem.svg"
  else
    echo "render_diagrams: graphviz 'dot' not installed: $stem.svg not refreshed" >&2
  fi
done
