#!/usr/bin/env bash
# Deploy.DebianPackage: cpack makes the .deb of this build tree; dpkg-deb shows the target's
# architecture (arm64 from the aarch64 tree, whatever the build host), the dependencies, the
# maintainer scripts, the conffile and the files a robot needs.
#   package_case.sh BUILD_DIR WORK_DIR ARCH PREFIX SYSCONFDIR HAVE_OPENCV
set -euo pipefail
build=$1 work=$2 arch=$3 prefix=$4 sysconfdir=$5 opencv=$6

fail() { printf 'FAIL: %s\n' "$*" >&2; exit 1; }
rm -rf "$work"
mkdir -p "$work"
if ! cpack --config "$build/CPackConfig.cmake" -B "$work" >"$work/cpack.log" 2>&1; then
  cat "$work/cpack.log" >&2
  fail "cpack failed"
fi
debs=("$work"/ringlet_*_"$arch".deb)
[[ -f ${debs[0]} ]] || fail "no ringlet_*_$arch.deb in $work: $(ls "$work")"
deb=${debs[0]}
echo "package: ${deb##*/} ($(stat -c %s "$deb") bytes)"

info=$(dpkg-deb -I "$deb")
field() { sed -n "s/^ $1: //p" <<<"$info"; }
[[ $(field Package) == ringlet ]] || fail "Package is '$(field Package)'"
[[ $(field Architecture) == "$arch" ]] || fail "Architecture is '$(field Architecture)', not $arch"
depends=$(field Depends)
for d in libc6 libstdc++6 iproute2; do
  grep -q "\b$d\b" <<<"$depends" || fail "Depends lacks $d: $depends"
done
# The OpenCV camera's libraries (dpkg-shlibdeps on the host; named by cmake/RingletPackage.cmake
# for the cross build's sysroot, whose libraries no installed package owns).
if [[ $opencv == 1 || $opencv == TRUE || $opencv == ON ]]; then
  grep -q "\blibopencv-videoio406\b" <<<"$depends" || fail "Depends lacks libopencv-videoio406: $depends"
fi
[[ -n $(field Maintainer) ]] || fail "no Maintainer"
for s in postinst prerm postrm conffiles; do grep -q "\b$s\b" <<<"$info" || fail "control lacks $s"; done
conffiles=$(dpkg-deb --ctrl-tarfile "$deb" | tar -xOf - ./conffiles)
[[ $conffiles == "$sysconfdir/ringlet/robot.toml" ]] || fail "conffiles: '$conffiles'"
echo "control: Architecture $arch; Depends: $depends"

files=$(dpkg-deb -c "$deb" | awk '{print $NF}')
for f in "$prefix/bin/ringlet" "$prefix/bin/ringlet-board-sim" "$prefix/bin/ringlet-monitor" \
         "$sysconfdir/ringlet/robot.toml" "$prefix/lib/systemd/system/ringlet.service" \
         "$prefix/lib/systemd/system/ringlet-can@.service" "$prefix/lib/sysusers.d/ringlet.conf" \
         "$prefix/share/ringlet/can/ringlet_board.dbc"; do
  grep -qx "\.$f" <<<"$files" || fail "the package lacks $f"
done
# The binaries are the target's: the ELF header names the machine.
dpkg-deb -x "$deb" "$work/x"
machine=$(readelf -h "$work/x$prefix/bin/ringlet" | sed -n 's/^ *Machine: *//p')
case $arch in
  arm64) [[ $machine == AArch64 ]] || fail "bin/ringlet is '$machine', not AArch64" ;;
  amd64) [[ $machine == *X86-64* ]] || fail "bin/ringlet is '$machine', not X86-64" ;;
esac
echo "files: binaries ($machine), robot.toml, units, sysusers, DBC"
echo "PASS"
