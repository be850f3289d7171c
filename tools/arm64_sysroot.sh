#!/usr/bin/env bash
# The arm64 OpenCV sysroot of the aarch64 cross build (README.md, "Cross-compiling").
#
# Debian's arm64 OpenCV packages cannot be installed next to the amd64 ones (libopencv-dev and
# libgdal32 would go), so they are never installed: this script resolves what the camera backend
# needs with apt-cache, downloads the .debs with `apt-get download` and unpacks them with
# `dpkg-deb -x` into a folder of its own:
#   headers + libopencv_*.so  libopencv-{core,imgproc,imgcodecs,videoio}-dev (not their Depends)
#   the runtime               libopencv-{core,imgproc,imgcodecs,videoio}406 and everything they
#                             depend on, recursively: packages of Section libs only, and none that
#                             is already installed as arm64 multiarch (libc6, libstdc++6, libgcc-s1
#                             and gcc-12-base never come from here: one glibc per process)
# The .debs are cached in ${RINGLET_CACHE:-~/.cache/ringlet}/arm64-sysroot/debs; the sysroot is
# unpacked again only when the list of packages and versions changes (a stamp in the sysroot).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SYSROOT="$ROOT/build/arm64-sysroot"
CACHE="${RINGLET_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/ringlet}/arm64-sysroot/debs"
MODULES=(core imgproc imgcodecs videoio)
SOVERSION=406
# Never from the sysroot: the C and C++ runtimes the cross toolchain and qemu use (multiarch).
NEVER=(libc6 libstdc++6 libgcc-s1 gcc-12-base)
# Bumped when the layout this script makes changes, so that old sysroots are unpacked again.
LAYOUT=1

usage() {
  cat <<EOF
Usage: tools/arm64_sysroot.sh [--sysroot DIR] [--print-libdirs] [--quiet]

Makes (or checks) the arm64 OpenCV sysroot of the aarch64 cross build: OpenCV's headers and
libraries for the modules ${MODULES[*]} and their runtime closure, from Debian's arm64 packages,
downloaded (never installed) and unpacked.

  --sysroot DIR     where to unpack (default: $SYSROOT; the aarch64 preset's
                    RINGLET_ARM64_SYSROOT)
  --print-libdirs   only print the sysroot's library folders, one a line (the sysroot must have
                    been made)
  --quiet           print only errors and the one-line summary
  -h, --help        this text

The .debs are cached in $CACHE. Needs apt-get, apt-cache, dpkg-deb,
aarch64-linux-gnu-readelf and the arm64 dpkg architecture (tools/ringlet deps sets them up).
EOF
}

say() { [[ -n "$QUIET" ]] || echo "arm64_sysroot: $*"; }
die() { echo "arm64_sysroot: error: $*" >&2; exit 1; }

PRINT_LIBDIRS=""
QUIET=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --sysroot) [[ $# -ge 2 ]] || die "--sysroot needs a folder"; SYSROOT="$2"; shift 2 ;;
    --sysroot=*) SYSROOT="${1#--sysroot=}"; shift ;;
    --print-libdirs) PRINT_LIBDIRS=1; shift ;;
    --quiet|-q) QUIET=1; shift ;;
    -h|--help) usage; exit 0 ;;
    *) usage >&2; die "unknown argument '$1'" ;;
  esac
done
[[ "$SYSROOT" == /* ]] || SYSROOT="$PWD/$SYSROOT"
STAMP="$SYSROOT/.ringlet-sysroot-stamp"
LIBDIRS_FILE="$SYSROOT/.ringlet-libdirs"

if [[ -n "$PRINT_LIBDIRS" ]]; then
  [[ -f "$LIBDIRS_FILE" ]] || die "$SYSROOT is not a finished sysroot (run tools/arm64_sysroot.sh first)"
  cat "$LIBDIRS_FILE"
  exit 0
fi

for tool in apt-get apt-cache dpkg-query dpkg-deb aarch64-linux-gnu-readelf; do
  command -v "$tool" >/dev/null || die "'$tool' not found (tools/ringlet deps installs what the cross build needs)"
done
dpkg --print-foreign-architectures | grep -qx arm64 ||
  die "arm64 is not a dpkg architecture here: dpkg --add-architecture arm64 && apt-get update (tools/ringlet deps does both)"

installed_arm64() { [[ "$(dpkg-query -W -f='${Status}' "$1:arm64" 2>/dev/null)" == "install ok installed" ]]; }
for p in "${NEVER[@]}"; do
  installed_arm64 "$p" || die "$p:arm64 is not installed: the sysroot never carries the C/C++ runtime (tools/ringlet deps installs it)"
done

# ---- which packages -------------------------------------------------------------------------
start=$(date +%s)
# Resolving takes apt-cache a minute: skipped while apt's lists, dpkg's status and this script
# are those the finished sysroot was made from.
APT_KEY_FILE="$SYSROOT/.ringlet-apt-key"
apt_key() {
  { echo "layout $LAYOUT ${MODULES[*]} $SOVERSION"
    stat -c '%n %s %Y' /var/lib/dpkg/status /var/lib/apt/lists/*_Packages* 2>/dev/null || true
    sha256sum "${BASH_SOURCE[0]}"; } | sha256sum | cut -d' ' -f1
}
if [[ -f "$STAMP" && -f "$LIBDIRS_FILE" && -f "$APT_KEY_FILE" && "$(cat "$APT_KEY_FILE")" == "$(apt_key)" ]]; then
  say "$SYSROOT is up to date ($(( $(wc -l < "$STAMP") - 1 )) packages; apt's lists unchanged since it was made)"
  [[ -n "$QUIET" ]] && echo "arm64_sysroot: $SYSROOT: up to date"
  exit 0
fi
DEV=()
RUNTIME=()
for m in "${MODULES[@]}"; do
  DEV+=("libopencv-$m-dev")
  RUNTIME+=("libopencv-$m$SOVERSION:arm64")
done
closure="$(apt-cache depends --recurse --no-recommends --no-suggests --no-conflicts --no-breaks \
             --no-replaces --no-enhances "${RUNTIME[@]}" 2>&1)" ||
  die "apt-cache depends failed for ${RUNTIME[*]}: $(tail -n 3 <<<"$closure") (apt-get update?)"
# The recursion heads are the unindented lines; <virtual> names are not packages.
mapfile -t CANDIDATES < <(sed -n 's/^\([a-z0-9][^ <>]*\):arm64$/\1/p' <<<"$closure" | sort -u)
[[ ${#CANDIDATES[@]} -gt 0 ]] || die "apt-cache knows no arm64 packages for ${RUNTIME[*]} (apt-get update?)"

# Package, version and section of every candidate and of the -dev packages, in one apt-cache call.
declare -A VERSION=() SECTION=()
while IFS='|' read -r p v s; do
  [[ -n "$p" ]] || continue
  VERSION[$p]="$v"
  SECTION[$p]="$s"
done < <(apt-cache show --no-all-versions "${CANDIDATES[@]/%/:arm64}" "${DEV[@]/%/:arm64}" 2>/dev/null |
           awk '/^Package:/{p=$2} /^Version:/{v=$2} /^Section:/{s=$2} /^$/{if(p!="") print p "|" v "|" s; p=""} END{if(p!="") print p "|" v "|" s}')
for p in "${DEV[@]}"; do
  [[ -n "${VERSION[$p]:-}" ]] || die "apt-cache show knows no $p:arm64 (apt-get update?)"
done

PKGS=("${DEV[@]}")
skipped_installed=()
skipped_other=()
for p in "${CANDIDATES[@]}"; do
  if [[ " ${NEVER[*]} " == *" $p "* ]] || installed_arm64 "$p"; then
    skipped_installed+=("$p")
  elif [[ "${SECTION[$p]:-}" != libs ]]; then
    skipped_other+=("$p")   # dpkg, tar, fontconfig, gdal-plugins...: tools and data, no NEEDED library
  else
    PKGS+=("$p")
  fi
done
mapfile -t PKGS < <(printf '%s\n' "${PKGS[@]}" | sort -u)
say "${#PKGS[@]} arm64 packages ($(( $(date +%s) - start )) s to resolve); not taken: ${#skipped_installed[@]} installed as arm64 multiarch (${skipped_installed[*]}), ${#skipped_other[@]} outside Section libs (${skipped_other[*]})"

deb_name() { local v="${VERSION[$1]}"; echo "${1}_${v//:/%3a}_arm64.deb"; }
want_stamp() {
  echo "layout $LAYOUT"
  local p
  for p in "${PKGS[@]}"; do echo "$p ${VERSION[$p]}"; done
}

# ---- download -------------------------------------------------------------------------------
mkdir -p "$CACHE" || die "cannot create the cache folder $CACHE"
missing=()
for p in "${PKGS[@]}"; do
  [[ -f "$CACHE/$(deb_name "$p")" ]] || missing+=("$p:arm64=${VERSION[$p]}")
done
if [[ ${#missing[@]} -gt 0 ]]; then
  say "apt-get download ${#missing[@]} packages into $CACHE"
  t0=$(date +%s)
  # apt's sandbox user cannot write a root-owned cache: download unsandboxed there.
  if ! out="$(cd "$CACHE" && apt-get download -o APT::Sandbox::User=root "${missing[@]}" 2>&1)"; then
    echo "$out" | tail -n 5 >&2
    die "apt-get download failed for some of: ${missing[*]}"
  fi
  say "downloaded ${#missing[@]} packages in $(( $(date +%s) - t0 )) s"
fi
for p in "${PKGS[@]}"; do
  [[ -f "$CACHE/$(deb_name "$p")" ]] || die "apt-get download left no $(deb_name "$p") in $CACHE"
done
bytes=0
for p in "${PKGS[@]}"; do bytes=$(( bytes + $(stat -c %s "$CACHE/$(deb_name "$p")") )); done

# ---- unpack (only when the list changed) ----------------------------------------------------
if [[ -f "$STAMP" && -f "$LIBDIRS_FILE" ]] && [[ "$(cat "$STAMP")" == "$(want_stamp)" ]]; then
  apt_key > "$APT_KEY_FILE"
  say "$SYSROOT is up to date (${#PKGS[@]} packages, $(( bytes / 1048576 )) MiB of .debs)"
  [[ -n "$QUIET" ]] && echo "arm64_sysroot: $SYSROOT: up to date, ${#PKGS[@]} packages"
  exit 0
fi
say "unpacking ${#PKGS[@]} packages into $SYSROOT"
rm -rf "$SYSROOT"
mkdir -p "$SYSROOT"
for p in "${PKGS[@]}"; do
  dpkg-deb -x "$CACHE/$(deb_name "$p")" "$SYSROOT" || die "dpkg-deb -x failed on $CACHE/$(deb_name "$p")"
done

# ---- check: every library the OpenCV modules load, transitively, is found -------------------
# In the sysroot's multiarch folders, else the host's arm64 multiarch ones (libc6:arm64, ...).
# A library elsewhere under usr/lib (libarmadillo in usr/lib itself, libblas.so.3 in a subfolder
# behind update-alternatives, which nothing here runs) has its folder added.
MAIN_DIRS=("$SYSROOT/usr/lib/aarch64-linux-gnu" "$SYSROOT/lib/aarch64-linux-gnu")
HOST_DIRS=(/lib/aarch64-linux-gnu /usr/lib/aarch64-linux-gnu)
LIBDIRS=()
for d in "${MAIN_DIRS[@]}"; do [[ -d "$d" ]] && LIBDIRS+=("$d"); done
find_lib() {
  local d hit
  for d in "${LIBDIRS[@]}" "${HOST_DIRS[@]}"; do
    if [[ -e "$d/$1" ]]; then echo "$d/$1"; return 0; fi
  done
  hit="$(find "$SYSROOT/usr/lib" "$SYSROOT/lib" -name "$1" 2>/dev/null | sort | head -1)"
  [[ -n "$hit" ]] || return 1
  LIBDIRS+=("$(dirname "$hit")")
  echo "$hit"
}
declare -A seen=()
queue=()
for m in "${MODULES[@]}"; do
  so="$SYSROOT/usr/lib/aarch64-linux-gnu/libopencv_$m.so"
  [[ -e "$so" ]] || die "libopencv-$m-dev:arm64 holds no usr/lib/aarch64-linux-gnu/libopencv_$m.so"
  queue+=("$so")
done
[[ -f "$SYSROOT/usr/include/opencv4/opencv2/core.hpp" ]] || die "no usr/include/opencv4/opencv2/core.hpp in $SYSROOT"
while [[ ${#queue[@]} -gt 0 ]]; do
  f="${queue[0]}"; queue=("${queue[@]:1}")
  while read -r lib; do
    [[ -n "${seen[$lib]:-}" ]] && continue
    seen[$lib]=1
    # Before find_lib in a $( ): a subfolder it finds must reach LIBDIRS in this shell.
    find_lib "$lib" >/dev/null || die "no arm64 $lib (needed by $(basename "$f")) in the sysroot or the arm64 multiarch folders"
    queue+=("$(find_lib "$lib")")
  done < <(aarch64-linux-gnu-readelf -d "$(readlink -f "$f")" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
done
printf '%s\n' "${LIBDIRS[@]}" > "$LIBDIRS_FILE"
want_stamp > "$STAMP"
apt_key > "$APT_KEY_FILE"
size="$(du -sm "$SYSROOT" | cut -f1)"
echo "arm64_sysroot: $SYSROOT: ${#PKGS[@]} packages ($(( bytes / 1048576 )) MiB of .debs), ${size} MiB unpacked, OpenCV's modules load ${#seen[@]} libraries; $(( $(date +%s) - start )) s"
