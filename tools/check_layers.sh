#!/usr/bin/env bash
# Ringlet layering check: dependencies point down (see the top-level CMakeLists.txt).
#
#   tools/check_layers.sh <repo-root>   check a tree; exit 1 and print
#                                       `file:line: <layer> must not include <other>` (or `link`)
#                                       for every violation
#   tools/check_layers.sh --self-test   build a throw-away tree with deliberate violations under
#                                       $TMPDIR and check that each one is caught
#
# Rules (a layer is a top-level folder):
#   1. nothing outside firmware/ and tests/ includes a firmware header: `ringlet/firmware/...`,
#      `firmware/...`, or any `ringlet/<x>/` folder that lives under firmware/**/include/
#      (e.g. `ringlet/executive/`), nor links a firmware target (`ringlet_firmware*` or any
#      target defined under firmware/);
#   2. hal/, behaviour/, vision/, planning/, whiteboard/ do not include sim_hal headers
#      (`ringlet/sim_hal/...`, `sim_hal/...`, or any `ringlet/<x>/` under sim_hal/**/include/) nor
#      link `ringlet_sim_hal` (or any target defined under sim_hal/);
#   3. hal/ does not include behaviour/, vision/, planning/ headers nor link their targets.
# CMake: every target_link_libraries / link_libraries / ringlet_library call in CMakeLists.txt
# and *.cmake files is read (comments removed, multi-line calls joined).
set -euo pipefail

SELF="${BASH_SOURCE[0]}"

usage() {
  echo "usage: $0 <repo-root> | --self-test" >&2
  exit 2
}

SIM_USERS=" hal behaviour vision planning whiteboard "
UPPER_LAYERS=(behaviour vision planning)
EXEMPT_FROM_FIRMWARE=" firmware tests "

# ---------------------------------------------------------------------------------------------

# Source files relative to the root (the root is the cwd), build outputs and hidden dirs skipped.
list_files() {
  find . \( ! -path . \( -name '.*' -o -path './build' -o -path './build-*' -o -path './out' \) \) \
    -prune -o -type f \( "$@" \) -print | sed 's|^\./||' | sort
}

src_files() {
  list_files -name '*.h' -o -name '*.hh' -o -name '*.hpp' -o -name '*.hxx' -o -name '*.ipp' \
    -o -name '*.inl' -o -name '*.tpp' -o -name '*.c' -o -name '*.cc' -o -name '*.cpp' \
    -o -name '*.cxx'
}

cmake_files() {
  list_files -name 'CMakeLists.txt' -o -name '*.cmake'
}

# `ringlet/<x>/` prefixes of the headers a layer ships (dirs <layer>/**/include/ringlet/<x>).
declare -A OWN_PREFIXES=()
discover_prefixes() {
  local layer="$1" d
  OWN_PREFIXES[$layer]=" "
  [[ -d "$layer" ]] || return 0
  while IFS= read -r d; do
    OWN_PREFIXES[$layer]+="ringlet/${d##*/}/ "
  done < <(find "$layer" -type d -path '*/include/ringlet/*' -prune -print)
}

# include_owner LAYER PATH: sets OWNER to the layer (firmware, sim_hal, behaviour, vision,
# planning) that owns the included PATH, unless LAYER ships that prefix itself; else to "".
OWNER=""
include_owner() {
  local includer="$1" p="$2" o pre
  OWNER=""
  p="${p#./}"
  while [[ "$p" == ../* ]]; do p="${p#../}"; done
  case "$p" in
    ringlet/firmware/*|firmware/*) OWNER=firmware; return 0 ;;
    ringlet/sim_hal/*|sim_hal/*) OWNER=sim_hal; return 0 ;;
    ringlet/behaviour/*|behaviour/*) OWNER=behaviour; return 0 ;;
    ringlet/vision/*|vision/*) OWNER=vision; return 0 ;;
    ringlet/planning/*|planning/*) OWNER=planning; return 0 ;;
  esac
  [[ "$p" == ringlet/*/* ]] || return 0
  pre="${p#ringlet/}"
  pre="ringlet/${pre%%/*}/"
  # hal/ headers are everybody's; a prefix the includer ships itself is its own.
  if [[ "$pre" == ringlet/hal/ || "${OWN_PREFIXES[$includer]:- }" == *" $pre "* ]]; then
    return 0
  fi
  for o in firmware sim_hal behaviour vision planning; do
    if [[ "${OWN_PREFIXES[$o]}" == *" $pre "* ]]; then
      OWNER="$o"
      return 0
    fi
  done
}

# forbidden LAYER OWNER: true if LAYER may not depend on OWNER.
forbidden() {
  local layer="$1" owner="$2" u
  if [[ "$layer" == "$owner" ]]; then return 1; fi
  case "$owner" in
    firmware) [[ "$EXEMPT_FROM_FIRMWARE" != *" $layer "* ]] ;;
    sim_hal) [[ "$SIM_USERS" == *" $layer "* ]] ;;
    *)
      for u in "${UPPER_LAYERS[@]}"; do
        if [[ "$owner" == "$u" && "$layer" == hal ]]; then return 0; fi
      done
      return 1 ;;
  esac
}

# Every CMake command call as: file<TAB>line<TAB>command(lower case)<TAB>arguments (one line).
cmake_calls() {
  local f
  while IFS= read -r f; do
    awk -v file="$f" '
      BEGIN { depth = 0; word = ""; inq = 0; inbracket = 0 }
      {
        line = $0
        if (inbracket) {
          k = index(line, "]]")
          if (k == 0) next
          line = substr(line, k + 2); inbracket = 0
        }
        n = length(line)
        for (i = 1; i <= n; i++) {
          c = substr(line, i, 1)
          if (inq) {
            if (c == "\\") { args = args c substr(line, i + 1, 1); i++; continue }
            if (c == "\"") inq = 0
            args = args c
            continue
          }
          if (c == "#") {
            if (substr(line, i + 1, 2) == "[[" || substr(line, i + 1, 3) == "[=[") {
              rest = substr(line, i + 3); k = index(rest, "]]")
              if (k == 0) { inbracket = 1; break }
              i = i + 2 + k + 1; continue
            }
            break
          }
          if (depth == 0) {
            if (c ~ /[A-Za-z0-9_]/) { word = word c; continue }
            if (c == "(" && word != "") { cmd = tolower(word); start = NR; depth = 1; args = ""; word = ""; continue }
            word = ""
            continue
          }
          if (c == "\"") { inq = 1; args = args c; continue }
          if (c == "(") depth++
          if (c == ")") {
            depth--
            if (depth == 0) { gsub(/[\t ]+/, " ", args); printf "%s\t%d\t%s\t%s\n", file, start, cmd, args; continue }
          }
          args = args c
        }
        if (depth > 0) args = args " "
        else word = ""
      }' "$f"
  done
}

check_tree() {
  local root="$1"
  [[ -d "$root" ]] || { echo "check_layers: no such directory: $root" >&2; exit 2; }
  cd "$root"

  local l
  for l in firmware sim_hal behaviour vision planning hal whiteboard tests; do
    discover_prefixes "$l"
  done

  local violations=0 nsrc=0 ncmake=0 file lineno text inc layer owner
  local include_re='^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"]([^>"]+)[>"]'

  # --- #include lines -------------------------------------------------------------------------
  local -a files=()
  mapfile -t files < <(src_files)
  nsrc=${#files[@]}
  if [[ $nsrc -gt 0 ]]; then
    while IFS= read -r hit; do
      file="${hit%%:*}"; hit="${hit#*:}"
      lineno="${hit%%:*}"; text="${hit#*:}"
      [[ "$file" == */* ]] || continue          # top-level files belong to no layer
      layer="${file%%/*}"
      [[ "$text" =~ $include_re ]] || continue
      inc="${BASH_REMATCH[1]}"
      include_owner "$layer" "$inc"
      owner="$OWNER"
      [[ -n "$owner" ]] || continue
      if forbidden "$layer" "$owner"; then
        echo "$file:$lineno: $layer must not include $owner ($inc)"
        violations=$((violations + 1))
      fi
    done < <(printf '%s\0' "${files[@]}" \
               | xargs -0 grep -nHE '^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"][^>"]+[>"]' \
               || true)
  fi

  # --- CMake: targets defined per layer, then link calls ---------------------------------------
  local -A target_owner=([ringlet_sim_hal]=sim_hal)
  local calls cmd args first tok t
  local -a toks
  calls="$(cmake_files | cmake_calls)"
  ncmake="$(cmake_files | wc -l)"
  while IFS=$'\t' read -r file lineno cmd args; do
    [[ -n "${file:-}" && "$file" == */* ]] || continue
    layer="${file%%/*}"
    case "$layer" in firmware|sim_hal|behaviour|vision|planning) ;; *) continue ;; esac
    case "$cmd" in add_library|add_executable|ringlet_library) ;; *) continue ;; esac
    read -r first _ <<<"$args"
    if [[ -n "$first" ]]; then target_owner[$first]="$layer"; fi
  done <<<"$calls"

  while IFS=$'\t' read -r file lineno cmd args; do
    [[ -n "${file:-}" && "$file" == */* ]] || continue
    layer="${file%%/*}"
    case "$cmd" in
      target_link_libraries|ringlet_library) read -r _ args <<<"$args" || true ;;
      link_libraries) ;;
      *) continue ;;
    esac
    read -r -a toks <<<"$(tr '";<>$,' '      ' <<<"${args:-}")" || true
    for tok in "${toks[@]}"; do
      t="$tok"
      if [[ "$t" == *:* && "$t" != *::* ]]; then t="${t##*:}"; fi
      owner="${target_owner[$t]:-}"
      if [[ -z "$owner" && "$t" == ringlet_firmware* ]]; then owner=firmware; fi
      [[ -n "$owner" ]] || continue
      if forbidden "$layer" "$owner"; then
        echo "$file:$lineno: $layer must not link $t ($owner)"
        violations=$((violations + 1))
      fi
    done
  done <<<"$calls"

  if [[ $violations -gt 0 ]]; then
    echo "check_layers: $violations layering violation(s)" >&2
    return 1
  fi
  echo "check_layers: OK ($nsrc source files, $ncmake CMake files)"
}

# ---------------------------------------------------------------------------------------------

self_test() {
  local tmp
  tmp="$(mktemp -d "${TMPDIR:-/tmp}/ringlet-layers.XXXXXX")"
  # shellcheck disable=SC2064
  trap "rm -rf '$tmp'" EXIT
  local fails=0 n=0

  # A clean tree that exercises every allowed edge (and comments that look like violations).
  make_clean_tree() {
    local t="$1"
    mkdir -p "$t"/{hal/include/ringlet/hal,hal/src,sim_hal/include/ringlet/sim_hal,sim_hal/src} \
      "$t"/{behaviour/src,vision/src,planning/src,whiteboard/src,tests/hal} \
      "$t"/firmware/executive/{include/ringlet/executive,src}
    printf '#pragma once\n#include <cstdint>\n' > "$t/hal/include/ringlet/hal/time.hpp"
    printf '#include "ringlet/hal/time.hpp"\n// #include "ringlet/firmware/x.hpp"\n' \
      > "$t/hal/src/clock.cpp"
    printf '#pragma once\n#include <ringlet/hal/time.hpp>\n' > "$t/sim_hal/include/ringlet/sim_hal/world.hpp"
    printf '#include "ringlet/sim_hal/world.hpp"\n' > "$t/sim_hal/src/world.cpp"
    printf '#include "ringlet/hal/time.hpp"\n/* #include "ringlet/sim_hal/world.hpp" */\n' \
      > "$t/behaviour/src/follow.cpp"
    printf '#include <ringlet/behaviour/follow.hpp>\n#include <ringlet/hal/time.hpp>\n' \
      > "$t/planning/src/dstar.cpp"
    printf '#pragma once\n' > "$t/firmware/executive/include/ringlet/executive/task.hpp"
    printf '#include "ringlet/executive/task.hpp"\n#include "ringlet/sim_hal/world.hpp"\n' \
      > "$t/firmware/executive/src/task.cpp"
    printf '#include "ringlet/firmware/config.hpp"\n#include "ringlet/executive/task.hpp"\n#include "ringlet/sim_hal/world.hpp"\n' \
      > "$t/tests/hal/t.cpp"
    printf 'ringlet_library(ringlet_hal SOURCES src/clock.cpp)\n# target_link_libraries(ringlet_hal PUBLIC ringlet_sim_hal)\n' \
      > "$t/hal/CMakeLists.txt"
    printf 'ringlet_library(ringlet_sim_hal SOURCES src/world.cpp PUBLIC ringlet_hal)\n' \
      > "$t/sim_hal/CMakeLists.txt"
    printf 'ringlet_library(ringlet_behaviour\n  SOURCES src/follow.cpp\n  PUBLIC ringlet_hal)\n' \
      > "$t/behaviour/CMakeLists.txt"
    printf 'add_library(ringlet_executive src/task.cpp)\ntarget_link_libraries(ringlet_executive PUBLIC ringlet_sim_hal ringlet_behaviour)\nadd_executable(ringlet main.cpp)\n' \
      > "$t/firmware/CMakeLists.txt"
    printf 'target_link_libraries(t PRIVATE ringlet_executive ringlet_sim_hal)\n' \
      > "$t/tests/hal/CMakeLists.txt"
  }

  # expect NAME WANT_RC EXPECTED_TEXT SETUP...: build a clean tree, apply SETUP (a command run
  # inside the tree), run the checker, compare exit status and output.
  expect() {
    local name="$1" want="$2" text="$3" t out rc
    shift 3
    n=$((n + 1))
    t="$tmp/case$n"
    make_clean_tree "$t"
    (cd "$t" && eval "$*")
    set +e
    out="$(bash "$SELF" "$t" 2>&1)"
    rc=$?
    set -e
    if [[ $rc -eq $want && ( -z "$text" || "$out" == *"$text"* ) ]]; then
      echo "ok   $name"
    else
      # shellcheck disable=SC2016
      echo "FAIL $name: wanted exit $want${text:+ and '$text'}, got exit $rc:"
      printf "       %s\n" "${out//$'\n'/$'\n       '}"
      fails=$((fails + 1))
    fi
  }

  expect "clean tree passes" 0 "check_layers: OK" true
  expect "behaviour includes ringlet/firmware/" 1 \
    "behaviour/src/bad.cpp:2: behaviour must not include firmware" \
    "printf '#include <vector>\n#include \"ringlet/firmware/executive.hpp\"\n' > behaviour/src/bad.cpp"
  expect "sim_hal includes a firmware header found under firmware/**/include" 1 \
    "sim_hal/src/bad.cpp:1: sim_hal must not include firmware (ringlet/executive/task.hpp)" \
    "printf '#include <ringlet/executive/task.hpp>\n' > sim_hal/src/bad.cpp"
  expect "hal includes ringlet/sim_hal/" 1 "hal/src/bad.cpp:1: hal must not include sim_hal" \
    "printf '  #  include <ringlet/sim_hal/world.hpp>\n' > hal/src/bad.cpp"
  expect "whiteboard includes ringlet/sim_hal/" 1 \
    "whiteboard/src/bad.cpp:1: whiteboard must not include sim_hal" \
    "printf '#include \"ringlet/sim_hal/world.hpp\"\n' > whiteboard/src/bad.cpp"
  expect "hal includes behaviour" 1 \
    "hal/include/ringlet/hal/bad.hpp:2: hal must not include behaviour" \
    "printf '#pragma once\n#include \"ringlet/behaviour/follow.hpp\"\n' > hal/include/ringlet/hal/bad.hpp"
  expect "hal includes planning by relative path" 1 "hal must not include planning" \
    "printf '#include \"../../planning/include/ringlet/planning/map.hpp\"\n' > hal/src/bad.cpp"
  expect "planning links ringlet_sim_hal (multi-line call)" 1 \
    "planning/CMakeLists.txt:2: planning must not link ringlet_sim_hal" \
    "printf 'add_library(ringlet_planning src/dstar.cpp)\ntarget_link_libraries(ringlet_planning\n  PUBLIC ringlet_hal\n  PRIVATE ringlet_sim_hal)\n' > planning/CMakeLists.txt"
  expect "vision links ringlet_firmware_* through ringlet_library" 1 \
    "vision/CMakeLists.txt:1: vision must not link ringlet_firmware_core" \
    "printf 'ringlet_library(ringlet_vision SOURCES src/a.cpp PRIVATE ringlet_firmware_core)\n' > vision/CMakeLists.txt"
  expect "behaviour links a target defined under firmware/" 1 \
    "behaviour must not link ringlet_executive (firmware)" \
    "printf 'target_link_libraries(ringlet_behaviour PRIVATE ringlet_executive)\n' >> behaviour/CMakeLists.txt"
  expect "hal links behaviour" 1 "hal must not link ringlet_behaviour (behaviour)" \
    "printf 'target_link_libraries(ringlet_hal PUBLIC \$<BUILD_INTERFACE:ringlet_behaviour>)\n' >> hal/CMakeLists.txt"

  echo "check_layers self-test: $((n - fails)) passed, $fails failed"
  [[ $fails -eq 0 ]]
}

case "${1:-}" in
  --self-test) [[ $# -eq 1 ]] || usage; self_test ;;
  -h|--help) usage ;;
  "") usage ;;
  *) [[ $# -eq 1 ]] || usage; check_tree "$1" ;;
esac
