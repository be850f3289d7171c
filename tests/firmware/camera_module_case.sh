#!/usr/bin/env bash
# The OpenCV camera is a module the binary loads from ../lib/ringlet/ beside its own folder
# (firmware/camera_opencv). A binary whose module is missing must refuse [camera] backend =
# "opencv" at start-up, naming where the configuration asks for it and the module's path, with
# exit code 2; and a configuration without the camera must not need the module at all.
#   camera_module_case.sh BIN CAMERA_CONFIG PLAIN_CONFIG WORKDIR [EMULATOR...]
set -u
bin=$1 camera_config=$2 plain_config=$3 work=$4
shift 4
emulator=("$@")

# shellcheck source=case_lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/case_lib.sh"

rm -rf "$work" && mkdir -p "$work/bin" || exit 1
cp "$bin" "$work/bin/ringlet" || exit 1

"${emulator[@]}" "$work/bin/ringlet" --config "$camera_config" --lockstep --duration 1 >"$work/stdout" 2>"$work/stderr"
rc=$?
[[ $rc == 2 ]] || fail "expected exit code 2 without the module, got $rc"
grep -q "opencv_camera.toml:[0-9]*:[0-9]*: camera.backend: cannot load the OpenCV camera module $work/lib/ringlet/ringlet_camera_opencv.so: " \
  "$work/stderr" || fail "the missing module is not named"

"${emulator[@]}" "$work/bin/ringlet" --config "$plain_config" --lockstep --duration 1 >"$work/stdout" 2>"$work/stderr"
rc=$?
[[ $rc == 0 || $rc == 3 ]] || fail "a configuration without the camera failed without the module: exit $rc"
echo "camera_module_case: OK"
