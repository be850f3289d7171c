#!/usr/bin/env bash
# The emulated-aarch64 stage (tools/aarch64_vm/README.md): build the image, boot it in
# qemu-system-aarch64 with the PREEMPT_RT kernel, bring the results back over the serial console
# and check them.
#
# Usage: run.sh BUILD_DIR OUT_DIR [SYSROOT_LIB_DIR...]
#   BUILD_DIR  the aarch64 build tree;  OUT_DIR gets the image, console.log and results.json/.md
# Bounded: the VM gets RINGLET_VM_TIMEOUT seconds (default 420); a VM that does not boot or does
# not finish fails naming what it saw last.
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
BUILD="${1:?usage: run.sh BUILD_DIR OUT_DIR [SYSROOT_LIB_DIR...]}"
OUT="${2:?usage: run.sh BUILD_DIR OUT_DIR [SYSROOT_LIB_DIR...]}"
shift 2
TIMEOUT="${RINGLET_VM_TIMEOUT:-420}"

command -v qemu-system-aarch64 >/dev/null ||
  { echo "run.sh: error: qemu-system-aarch64 not found (Debian qemu-system-arm; tools/ringlet deps)" >&2; exit 1; }

bash "$HERE/make_image.sh" "$BUILD" "$OUT" "$@"

# Two CPUs: the board and the firmware each get one, as on a robot whose board is another
# computer. No network card (its option ROM is not installed, nor needed). cortex-a72: the NAO-class board's core family, and cheaper to emulate than -cpu max.
echo "run.sh: booting qemu-system-aarch64 (at most ${TIMEOUT}s); console in $OUT/console.log"
rm -f "$OUT/console.log"
start=$(date +%s)
status=0
timeout --kill-after=10 "$TIMEOUT" qemu-system-aarch64 \
  -machine virt -cpu cortex-a72 -smp 2 -m 1024 -nic none \
  -kernel "$OUT/vmlinuz" -initrd "$OUT/initramfs.cpio.gz" \
  -append "console=ttyAMA0 rdinit=/init panic=-1 quiet loglevel=1" \
  -display none -monitor none -serial "file:$OUT/console.log" -no-reboot || status=$?
echo "run.sh: the VM ran $(( $(date +%s) - start ))s (qemu exit $status)"
if [[ $status -eq 124 || $status -eq 137 ]]; then
  echo "run.sh: error: the VM did not finish within ${TIMEOUT}s; its console ends with:" >&2
  tail -n 15 "$OUT/console.log" >&2 || true
  exit 1
fi
if [[ $status -ne 0 ]]; then
  echo "run.sh: error: qemu-system-aarch64 failed (exit $status) before the VM could run" >&2
  exit 1
fi
python3 "$HERE/check.py" "$OUT/console.log" "$OUT"
