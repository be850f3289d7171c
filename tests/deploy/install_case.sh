#!/usr/bin/env bash
# Deploy.InstallTree: `cmake --install` of this build tree into a temporary DESTDIR, then what a
# robot needs from it: the layout, the installed binary runs, the shipped configurations validate
# with it from the install tree, robot.toml gets as far as opening the bus, and the systemd
# units' command line is one the installed binary accepts.
#   install_case.sh CMAKE BUILD_DIR WORK_DIR PREFIX SYSCONFDIR HAVE_OPENCV [EMULATOR...]
set -euo pipefail
cmake_bin=$1 build=$2 work=$3 prefix=$4 sysconfdir=$5 opencv=$6
shift 6
emulator=("$@")   # qemu-aarch64 in the cross tree, nothing on the host

fail() { printf 'FAIL: %s\n' "$*" >&2; exit 1; }
rm -rf "$work"
mkdir -p "$work"
root=$work/root
if ! DESTDIR=$root "$cmake_bin" --install "$build" >"$work/install.log" 2>&1; then
  cat "$work/install.log" >&2
  fail "cmake --install failed (is every installed target built? cmake --build $build)"
fi

p=$root$prefix
etc=$root$sysconfdir/ringlet
bins=(ringlet ringlet-board-sim ringlet-monitor ringlet-jitter ringlet-can-spec)
[[ $opencv == 1 || $opencv == TRUE || $opencv == ON ]] && bins+=(ringlet-vision ringlet-vision-calibrate)
for b in "${bins[@]}"; do [[ -x $p/bin/$b ]] || fail "missing executable bin/$b"; done
for f in share/ringlet/can/ringlet_board.dbc share/ringlet/idl/ringlet_wb.idl \
         share/ringlet/firmware/config/courtyard.toml share/ringlet/firmware/config/spl_field.toml \
         share/ringlet/sim_hal/worlds/courtyard.world share/ringlet/vision/models/ball.hog \
         lib/systemd/system/ringlet.service lib/systemd/system/ringlet-can@.service \
         lib/sysusers.d/ringlet.conf share/doc/ringlet/README.md; do
  [[ -f $p/$f ]] || fail "missing $f under $prefix"
done
[[ -f $etc/robot.toml ]] || fail "missing $sysconfdir/ringlet/robot.toml"
echo "layout: ${#bins[@]} programs, configurations, worlds, DBC, units, robot.toml"
# Nothing installed points into the build machine (the cross build's build rpath to its sysroot).
for b in "${bins[@]}"; do
  rpath=$(readelf -d "$p/bin/$b" | grep -E '\((RPATH|RUNPATH)\)' || true)
  [[ -z $rpath ]] || fail "installed bin/$b carries an rpath: $rpath"
done
echo "no installed program carries an rpath"
# The OpenCV camera's module, where the binary looks for it (../lib/ringlet/ from bin/), with its
# entry point and no rpath either.
if [[ $opencv == 1 || $opencv == TRUE || $opencv == ON ]]; then
  module=$p/lib/ringlet/ringlet_camera_opencv.so
  [[ -f $module ]] || fail "missing lib/ringlet/ringlet_camera_opencv.so (the OpenCV camera's module)"
  # Read whole before grep: with pipefail, grep -q leaving early kills readelf with SIGPIPE, and a
  # sanitizer build's module has enough symbols for that to fail the check.
  syms=$(readelf -W --dyn-syms "$module")
  grep -q ' ringlet_open_opencv_camera$' <<<"$syms" || fail "the module lacks ringlet_open_opencv_camera"
  rpath=$(readelf -d "$module" | grep -E '\((RPATH|RUNPATH)\)' || true)
  [[ -z $rpath ]] || fail "the installed camera module carries an rpath: $rpath"
  if grep -q 'NEEDED.*libopencv' <<<"$(readelf -d "$p/bin/ringlet")"; then fail "bin/ringlet links OpenCV (it must load the module)"; fi
  echo "the camera module is in lib/ringlet, without an rpath; bin/ringlet does not link OpenCV"
  # ringlet-vision's default models are the installed ones (share/ringlet/vision/models beside
  # bin/), not the source tree it was built from, which the robot does not have.
  if [[ -n ${VISION_IMAGE:-} ]]; then
    json=$("${emulator[@]}" "$p/bin/ringlet-vision" "$VISION_IMAGE" --compact 2>&1) || fail "installed ringlet-vision: $json"
    want="\"models\":{\"ball\":\"$p/share/ringlet/vision/models/ball.hog\",\"robot\":\"$p/share/ringlet/vision/models/robot.hog\"}"
    grep -qF "$want" <<<"$json" || fail "installed ringlet-vision does not default to the installed models: $json"
    echo "installed ringlet-vision verifies with share/ringlet/vision/models by default"
  fi
fi

run() { "${emulator[@]}" "$p/bin/ringlet" "$@"; }
help=$(run --help)
grep -q -- '--realtime' <<<"$help" || fail "installed ringlet --help does not list --realtime"

# A shipped configuration from the install tree: ../../sim_hal/worlds must resolve there.
out=$(run --config "$p/share/ringlet/firmware/config/courtyard.toml" --check 2>&1) ||
  fail "installed courtyard.toml does not validate: $out"
grep -q 'configuration OK' <<<"$out" || fail "no 'configuration OK' for courtyard.toml: $out"
echo "installed ringlet --check accepts share/ringlet/firmware/config/courtyard.toml"

# The unit's command line, run against the install tree with --check: the flags are the binary's,
# and robot.toml is parsed and checked until the board's interface is opened. This machine may
# have no can0 (exit 2 naming can.interface), a robot does (exit 0).
unit=$p/lib/systemd/system/ringlet.service
exec_line=$(sed -n 's/^ExecStart=//p' "$unit")
read -r -a argv <<<"$exec_line"
[[ ${argv[0]} == "$prefix/bin/ringlet" ]] || fail "ExecStart runs ${argv[0]}, not $prefix/bin/ringlet"
for i in "${!argv[@]}"; do
  case ${argv[$i]} in
    "$prefix"/*) argv[$i]=$root${argv[$i]} ;;
    "$sysconfdir"/*) argv[$i]=$root${argv[$i]} ;;
    /var/lib/ringlet/*) argv[$i]=$work/${argv[$i]##*/} ;;
  esac
done
[[ -x ${argv[0]} ]] || fail "ExecStart's binary is not installed: ${argv[0]}"
set +e
out=$("${emulator[@]}" "${argv[@]}" --check 2>&1)
rc=$?
set -e
if [[ $rc == 0 ]]; then
  grep -q 'configuration OK.*can backend' <<<"$out" || fail "robot.toml: exit 0 without 'configuration OK': $out"
  echo "ExecStart --check: robot.toml OK (this machine has the interface)"
elif [[ $rc == 2 ]] && grep -Eq 'robot\.toml:[0-9]+:[0-9]+: can\.interface: ' <<<"$out"; then
  echo "ExecStart --check: robot.toml valid up to opening the bus: ${out##*can.interface: }"
else
  fail "ExecStart --check: exit $rc, not the bus: $out"
fi

# The rest of robot.toml (task table, contracts, camera and vision settings) behind the simulator:
# the same file with the sim backend, the rendered camera and a world.
variant=$work/robot_on_sim.toml
sed -e 's/^backend = "can".*/backend = "sim"/' -e 's/^backend = "opencv".*/backend = "robot"/' \
    -e '/^source = /d' "$etc/robot.toml" >"$variant"
printf '\n[sim]\nworld = "%s"\n' "$p/share/ringlet/sim_hal/worlds/courtyard.world" >>"$variant"
out=$(run --config "$variant" --check 2>&1) || fail "robot.toml's table on the simulator: $out"
grep -q 'configuration OK' <<<"$out" || fail "robot.toml on the simulator: $out"
grep -q 'failsafe' <<<"$out" || fail "robot.toml's table has no failsafe row: $out"
echo "robot.toml's task table and contracts validate (sim backend)"

# The units as systemd reads them, where systemd-analyze is installed. It resolves the units' paths
# inside --root: a root with this host's units (sysinit.target, ...), ours, and the programs the
# units run at the paths they name (the installed ringlet; this host's ip, as iproute2 on the robot).
if command -v systemd-analyze >/dev/null 2>&1 && [[ -d /usr/lib/systemd/system ]]; then
  vroot=$work/verify
  mkdir -p "$vroot/usr/lib/systemd/system" "$vroot$prefix/bin"
  cp -r /usr/lib/systemd/system/. "$vroot/usr/lib/systemd/system/"
  cp "$unit" "$p/lib/systemd/system/ringlet-can@.service" "$vroot/usr/lib/systemd/system/"
  ln -f "$p/bin/ringlet" "$vroot$prefix/bin/ringlet"
  ip_path=$(sed -n 's/^ExecStart=\([^ ]*\) .*/\1/p' "$p/lib/systemd/system/ringlet-can@.service" | head -n 1)
  mkdir -p "$vroot${ip_path%/*}"
  if [[ -x $ip_path ]]; then cp "$ip_path" "$vroot$ip_path"; else printf '#!/bin/sh\n' >"$vroot$ip_path"; chmod +x "$vroot$ip_path"; fi
  units=("$vroot/usr/lib/systemd/system/ringlet.service" "$vroot/usr/lib/systemd/system/ringlet-can@can0.service")
  out=$(SYSTEMD_LOG_LEVEL=warning systemd-analyze verify --root="$vroot" "${units[@]}" 2>&1) ||
    fail "systemd-analyze verify: $out"
  [[ -z $out ]] || fail "systemd-analyze verify warns: $out"
  echo "systemd-analyze verify: ringlet.service and ringlet-can@can0.service clean"
else
  echo "systemd-analyze not installed: units not verified"
fi
echo "PASS"
