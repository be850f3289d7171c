#!/usr/bin/env bash
# Builds what the emulated aarch64 Linux boots (tools/aarch64_vm/README.md): the PREEMPT_RT arm64
# kernel and an initramfs holding busybox, iproute2's `ip`, candump, the CAN modules, the aarch64
# firmware `ringlet` and `ringlet-board-sim`, every shared library they load, and the files the
# runs read. Everything comes from Debian arm64 packages fetched with `apt-get download` and
# unpacked with `dpkg-deb -x`, never installed: installing e.g. iproute2:arm64 (Multi-Arch:
# foreign) would remove the host's own. The libraries the cross build linked against (toml++,
# Cyclone DDS, libstdc++, ...) come from the host's arm64 multiarch directories, where
# `tools/ringlet deps` installed them for the cross build, and from the arm64 sysroot if one is
# given.
#
# Usage: make_image.sh BUILD_DIR OUT_DIR [SYSROOT_LIB_DIR...]
#   BUILD_DIR  the aarch64 build tree (firmware/ringlet, sim_hal/ringlet-board-sim)
#   OUT_DIR    gets vmlinuz and initramfs.cpio.gz
# The .debs are cached in ${RINGLET_CACHE:-~/.cache/ringlet}/vm-debs, so a second run only
# repacks. Exit 1 with a message naming what is missing.
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
BUILD="${1:?usage: make_image.sh BUILD_DIR OUT_DIR [SYSROOT_LIB_DIR...]}"
OUT="${2:?usage: make_image.sh BUILD_DIR OUT_DIR [SYSROOT_LIB_DIR...]}"
shift 2
EXTRA_LIB_DIRS=("$@")
CACHE="${RINGLET_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/ringlet}/vm-debs"

say() { echo "make_image: $*"; }
die() { echo "make_image: error: $*" >&2; exit 1; }

for bin in firmware/ringlet sim_hal/ringlet-board-sim; do
  [[ -x "$BUILD/$bin" ]] || die "$BUILD/$bin is missing: build the aarch64 preset first"
done
for tool in apt-get apt-cache dpkg-deb cpio gzip aarch64-linux-gnu-readelf; do
  command -v "$tool" >/dev/null || die "'$tool' not found (tools/ringlet deps installs it)"
done
mkdir -p "$CACHE" "$OUT"

# ---- the packages ---------------------------------------------------------------------------
# The RT kernel's real package name carries the ABI number, which moves: ask the metapackage.
kernel_pkg() {
  apt-cache depends linux-image-rt-arm64:arm64 2>/dev/null |
    sed -n 's/^ *Depends: \(linux-image-[0-9][^: ]*-rt-arm64\).*/\1/p' | head -1
}
KERNEL_PKG="$(kernel_pkg)"
[[ -n "$KERNEL_PKG" ]] || die "apt-cache knows no linux-image-rt-arm64:arm64 (is arm64 a dpkg architecture? dpkg --add-architecture arm64 && apt-get update)"

# The shared-library packages under the tools (only lib* packages: dpkg, tar, debconf and the like
# are Depends of maintainer scripts that never run here).
lib_closure() {
  apt-cache depends --recurse --no-recommends --no-suggests --no-conflicts --no-breaks \
    --no-replaces --no-enhances "$@" 2>/dev/null |
    sed -n 's/^\(lib[^ <>]*\):arm64$/\1/p' | sort -u
}
PKGS=("$KERNEL_PKG" busybox-static iproute2 can-utils)
mapfile -t LIBS < <(lib_closure iproute2:arm64 can-utils:arm64)
PKGS+=("${LIBS[@]}")

fetch() {
  local missing=() p
  for p in "$@"; do
    compgen -G "$CACHE/${p}_*_arm64.deb" >/dev/null || missing+=("$p:arm64")
  done
  if [[ ${#missing[@]} -gt 0 ]]; then
    say "apt-get download ${#missing[@]} packages into $CACHE"
    # apt's sandbox user cannot write a root-owned cache: download unsandboxed there.
    (cd "$CACHE" && apt-get download -o APT::Sandbox::User=root "${missing[@]}") >/dev/null ||
      die "apt-get download failed for: ${missing[*]}"
  fi
}
fetch "${PKGS[@]}"

STAGE="$(mktemp -d "${TMPDIR:-/tmp}/ringlet-vm-stage.XXXXXX")"
trap 'rm -rf "$STAGE"' EXIT
DEBROOT="$STAGE/debs"   # every package unpacked
IMG="$STAGE/root"       # the initramfs
mkdir -p "$DEBROOT" "$IMG"
for p in "${PKGS[@]}"; do
  deb="$(compgen -G "$CACHE/${p}_*_arm64.deb" | sort -V | tail -1)"
  dpkg-deb -x "$deb" "$DEBROOT"
done

# ---- the kernel and its CAN modules ---------------------------------------------------------
vmlinuz="$(compgen -G "$DEBROOT/boot/vmlinuz-*" | head -1)" || true
[[ -n "$vmlinuz" ]] || die "$KERNEL_PKG holds no /boot/vmlinuz-*"
cp "$vmlinuz" "$OUT/vmlinuz"
kver="$(basename "$vmlinuz")"; kver="${kver#vmlinuz-}"
mkdir -p "$IMG/lib/modules"
# In load order: vcan needs can-dev, can-raw needs can.
for m in net/can/can.ko net/can/can-raw.ko drivers/net/can/dev/can-dev.ko drivers/net/can/vcan.ko; do
  src="$DEBROOT/lib/modules/$kver/kernel/$m"
  [[ -f "$src" ]] || die "$KERNEL_PKG has no $m"
  cp "$src" "$IMG/lib/modules/"
done

# ---- programs and their libraries -----------------------------------------------------------
mkdir -p "$IMG/bin" "$IMG/opt/ringlet/bin" "$IMG/lib/aarch64-linux-gnu" "$IMG/ringlet" "$IMG/tmp" "$IMG/proc" "$IMG/sys" "$IMG/dev"
cp "$DEBROOT/bin/busybox" "$IMG/bin/busybox"
# In /opt/ringlet/bin, first on the VM's PATH: `busybox --install` puts its applets (its own
# `ip` among them) wherever it likes in /bin, /sbin and /usr.
BIN="$IMG/opt/ringlet/bin"
cp "$DEBROOT/bin/ip" "$DEBROOT/usr/bin/candump" "$BUILD/firmware/ringlet" "$BUILD/sim_hal/ringlet-board-sim" "$BIN/"

LIB_DIRS=("$DEBROOT/lib/aarch64-linux-gnu" "$DEBROOT/usr/lib/aarch64-linux-gnu"
          "${EXTRA_LIB_DIRS[@]}" /lib/aarch64-linux-gnu /usr/lib/aarch64-linux-gnu)
find_lib() {
  local d
  for d in "${LIB_DIRS[@]}"; do
    if [[ -e "$d/$1" ]]; then echo "$d/$1"; return 0; fi
  done
  return 1
}
# Every NEEDED library, transitively, into /lib/aarch64-linux-gnu (the loader's default path).
declare -A have=()
queue=("$BIN/ip" "$BIN/candump" "$BIN/ringlet" "$BIN/ringlet-board-sim")
while [[ ${#queue[@]} -gt 0 ]]; do
  f="${queue[0]}"; queue=("${queue[@]:1}")
  while read -r lib; do
    [[ -n "${have[$lib]:-}" ]] && continue
    have[$lib]=1
    path="$(find_lib "$lib")" || die "no arm64 $lib (needed by $(basename "$f")) in ${LIB_DIRS[*]}"
    cp -L "$path" "$IMG/lib/aarch64-linux-gnu/$lib"
    queue+=("$IMG/lib/aarch64-linux-gnu/$lib")
  done < <(aarch64-linux-gnu-readelf -d "$f" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
done
loader="$(find_lib ld-linux-aarch64.so.1)" || die "no arm64 ld-linux-aarch64.so.1"
cp -L "$loader" "$IMG/lib/ld-linux-aarch64.so.1"

# ---- what the runs read ---------------------------------------------------------------------
cp "$HERE/init" "$IMG/init"
chmod +x "$IMG/init"
# The shipped CAN configuration, with allowances for full-system emulation, which translates each
# piece of code the first time it runs and shares two host cores with whatever else runs: the
# first frame takes 100s of ms, and on a loaded host a 10 Hz heartbeat came 450 ms late and one
# sense activation took 1.6 s. Function is what the VM proves; the allowances keep it from
# failing by chance (tools/aarch64_vm/README.md).
emulation_config() {
  sed -e 's/^watchdog_periods = [0-9]*/watchdog_periods = 300/' \
      -e 's/^heartbeat_timeout_ms = [0-9]*/heartbeat_timeout_ms = 3000/' \
      -e 's/^sensor_timeout_ms = [0-9]*/sensor_timeout_ms = 1000/' \
      -e 's/^laser_timeout_ms = [0-9]*/laser_timeout_ms = 3000/' "$1"
}
emulation_config "$ROOT/firmware/config/courtyard_can.toml" > "$IMG/ringlet/courtyard_can.toml"
for key in "watchdog_periods = 300" "heartbeat_timeout_ms = 3000" "sensor_timeout_ms = 1000" "laser_timeout_ms = 3000"; do
  grep -q "^$key" "$IMG/ringlet/courtyard_can.toml" ||
    die "firmware/config/courtyard_can.toml has no '${key%% =*}' line for the emulation's allowance"
done
cp "$ROOT/sim_hal/worlds/courtyard.world" "$IMG/ringlet/"

(cd "$IMG" && find . -print0 | cpio --null -o -H newc --quiet) | gzip -1 > "$OUT/initramfs.cpio.gz"
say "$KERNEL_PKG, $(( $(stat -c %s "$OUT/initramfs.cpio.gz") / 1024 )) KiB initramfs, ${#have[@]} libraries -> $OUT"
